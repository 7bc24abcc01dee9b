#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/worlds/SiteFiles.hpp"
#include "tests/support/FileText.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::house {
namespace {

const std::string kRoot = std::string(NXTMAP_SOURCE_DIR) + "/worlds/";

TEST(HouseMapper, ThreeRoomsWithALoopOfDoorways) {
  const sim::WorldLoad l = sim::World::load(kRoot + "houses/three-rooms.map");
  ASSERT_TRUE(l.world) << l.error;
  HouseConfig config;
  config.startCol = 8;
  config.startRow = 8;
  HouseMapper m(*l.world, config);
  EXPECT_EQ(m.run(), 3);
  const network::HouseNetwork& n = m.network();
  std::string error;
  EXPECT_TRUE(n.validate(error)) << error;
  // Three doorways: two passed, the third found from both sides joins two mapped rooms.
  EXPECT_EQ(n.gateways().size(), 3u);
  EXPECT_EQ(m.exitsUnreached(), 0);
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) EXPECT_FALSE(n.roomRoute(a, b).empty());
  }
  const HouseScore s = scoreHouse(m);
  EXPECT_GE(s.agreementPct(), 99.0);
  EXPECT_EQ(s.wrong, 0);
  // Every gateway's cells are the same world cells seen from both rooms.
  for (const network::Gateway& g : n.gateways()) {
    const auto& ra = n.rooms()[static_cast<size_t>(g.roomA)];
    const auto& rb = n.rooms()[static_cast<size_t>(g.roomB)];
    ASSERT_EQ(g.cellsA.size(), g.cellsB.size());
    for (size_t i = 0; i < g.cellsA.size(); ++i) {
      int ca, rowA, cb, rowB;
      m.houseFrame().toWorld(ra.toHouse.apply(g.cellsA[i]), ca, rowA);
      m.houseFrame().toWorld(rb.toHouse.apply(g.cellsB[i]), cb, rowB);
      EXPECT_EQ(ca, cb);
      EXPECT_EQ(rowA, rowB);
      EXPECT_FALSE(l.world->blocked(ca, rowA));
    }
  }
}

// Set down 8 degrees off square, the first room's run sweeps square to the walls (and the truth is laid on the
// grid it then maps on); without the sweep the whole house is mapped 8 degrees off. Later rooms do not sweep.
TEST(HouseMapper, AHouseSetDownOffSquareIsMappedSquareAfterTheFirstRoomsSweep) {
  const sim::WorldLoad l = sim::World::load(kRoot + "houses/three-rooms.map");
  ASSERT_TRUE(l.world) << l.error;
  double sum[2] = {0, 0};
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    double pct[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      HouseConfig config;
      config.startCol = 8;
      config.startRow = 8;
      config.startJitterDeg = 8;
      config.seed = seed;
      config.squareAtStart = k == 0;
      HouseMapper m(*l.world, config);
      const int rooms = m.run();
      if (k == 0) {  // (as set down, a room may be missed)
        EXPECT_EQ(rooms, 3) << "seed " << seed;
      }
      pct[k] = scoreHouse(m).agreementPct();
    }
    EXPECT_GE(pct[0], 85.0) << "seed " << seed;
    sum[0] += pct[0];
    sum[1] += pct[1];
  }
  // On the mean: one run as set down may come close (side walls take some of the heading out: seeds 1-3 measured
  // 77.9, 75.5 and 85.2 % as set down, 89.8 swept).
  EXPECT_GT(sum[0] / 3, sum[1] / 3 + 5.0) << "swept " << sum[0] / 3 << " %, as set down " << sum[1] / 3 << " %";
}

TEST(HouseMapper, HouseExpoPlanRoomByRoom) {
  const HousePlanLoad l = loadHouseExpo(kRoot + "houseexpo/1f99717550c31ae321ca2313edceedcc.json");
  ASSERT_TRUE(l.plan) << l.error;
  HouseConfig config;
  ASSERT_TRUE(defaultStart(*l.plan, config.startCol, config.startRow));
  HouseMapper m(l.plan->world, config);
  EXPECT_EQ(m.run(), 2);  // kitchen and living room
  EXPECT_EQ(m.network().gateways().size(), 1u);
  const HouseScore s = scoreHouse(m);
  EXPECT_GE(s.agreementPct(), 99.0);
  const PlanCoverage c = planCoverage(m, *l.plan);
  EXPECT_EQ(c.covered, c.reachable);
  EXPECT_EQ(c.reachable, 2);
  // The plan's rooms placed by their boxes on the plane give the same on the plan's own grid.
  const PlanCoverage onGrid = planCoverageOnGrid(m, *l.plan);
  EXPECT_EQ(onGrid.reachable, c.reachable);
  EXPECT_EQ(onGrid.covered, c.covered);
}

// The brick maps on 20 cm cells, squared to the walls, while the plan is rasterised at 10 cm: its rooms are
// placed on the brick's grid by their boxes in the plane. Before the run nothing covers them; after it all do.
TEST(HouseMapper, TheBricksCoverageOfAPlanCountsThePlanRoomsOnItsOwnGrid) {
  const std::string path = kRoot + "houseexpo/1f99717550c31ae321ca2313edceedcc.json";
  const HousePlanLoad plan = loadHouseExpo(path);
  ASSERT_TRUE(plan.plan) << plan.error;
  const sim::RobotDescription brick = *sim::robotByName("brick");
  worlds::SiteLoad l = worlds::loadSite(path, brick.cellCm);
  ASSERT_TRUE(l.site && l.site->start) << l.error;
  for (const double jitter : {0.0, 8.0}) {
    HouseConfig config;
    config.robot = brick;
    config.startPose = *l.site->start;
    config.startJitterDeg = jitter;
    config.squareAtStart = true;
    HouseMapper m(*l.site, config);
    const PlanCoverage before = planCoverageOnGrid(m, *plan.plan);
    EXPECT_EQ(before.reachable, 2) << jitter;
    EXPECT_EQ(before.covered, 0) << jitter;
    m.run();
    const PlanCoverage after = planCoverageOnGrid(m, *plan.plan);
    EXPECT_EQ(after.reachable, 2) << jitter;
    EXPECT_EQ(after.covered, 2) << jitter;
    // The rooms are named the same way: each label on a free cell of a mapped room, inside its plan box.
    labelRoomsFromPlan(m, *plan.plan, true);
    std::map<std::string, Cell> labels;  // name -> house cell
    for (const network::RoomNode& n : m.network().rooms())
      for (const auto& [name, cell] : n.labels) labels[name] = n.toHouse.apply(cell);
    ASSERT_EQ(labels.size(), 2u) << jitter;
    for (const PlanRoom& r : plan.plan->rooms) {
      std::string name = r.category;
      for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      ASSERT_EQ(labels.count(name), 1u) << name;
      int col = 0, row = 0;
      m.houseFrame().toWorld(labels[name], col, row);
      const sim::Vec2 p = m.robot().frame().toPlane(sim::Vec2(col, row));
      EXPECT_TRUE(r.containsPoint(p.x(), p.y())) << name << " at " << col << "," << row;
    }
  }
}

TEST(HouseMapper, SameSeedSameHouse) {
  const sim::WorldLoad l = sim::World::load(kRoot + "houses/three-rooms.map");
  ASSERT_TRUE(l.world);
  HouseConfig config;
  config.startCol = 8;
  config.startRow = 8;
  config.noise = *sim::noiseProfileByName("typical");
  config.seed = 7;
  HouseMapper a(*l.world, config), b(*l.world, config);
  a.run();
  b.run();
  ASSERT_EQ(a.network().rooms().size(), b.network().rooms().size());
  EXPECT_TRUE(a.network().merged() == b.network().merged());
  EXPECT_EQ(a.counters().explore.sensorRequests, b.counters().explore.sensorRequests);
}

}  // namespace
}  // namespace nxtmap::house

namespace nxtmap::house {
namespace {

const std::string kWorlds = std::string(NXTMAP_SOURCE_DIR) + "/worlds/";

TEST(HouseMapper, AMappedHouseSavesReloadsAndSavesTheSameBytes) {
  const HousePlanLoad l = loadHouseExpo(kWorlds + "houseexpo/house_expo_room_0000.json");
  ASSERT_TRUE(l.plan) << l.error;
  HouseConfig config;
  ASSERT_TRUE(defaultStart(*l.plan, config.startCol, config.startRow));
  HouseMapper m(l.plan->world, config);
  m.run();
  labelRoomsFromPlan(m, *l.plan);
  test::TempDir t("mapped_house");
  std::string e;
  ASSERT_TRUE(network::saveHouse(m.network(), 0.1, t.path("a"), e)) << e;
  const network::HouseLoad back = network::loadHouse(t.path("a"));
  ASSERT_TRUE(back.network) << back.error;
  EXPECT_TRUE(back.network->merged() == m.network().merged());
  ASSERT_TRUE(network::saveHouse(*back.network, back.resolutionM, t.path("b"), e)) << e;
  int files = 0;
  for (const auto& f : std::filesystem::directory_iterator(t.path("a"))) {
    ++files;
    const std::string name = f.path().filename().string();
    EXPECT_EQ(test::readWholeFile(t.path("a/" + name)), test::readWholeFile(t.path("b/" + name))) << name;
  }
  EXPECT_EQ(files, 1 + 2 * static_cast<int>(m.network().rooms().size()));
}

// A doorway seen from one room may fall a cell into the next room's wall (the two rooms' maps registered a
// cell apart). The planner's gateway then keeps only the cells both rooms can pass, so the house it builds
// is always one `save` accepts. The brick under nxt, set down off square: the plans and seeds where a gateway
// held such a cell (3 of 100 runs: seeds 1-20 of the five plans), and one that never did.
TEST(HouseMapper, EveryHouseTheBrickMapsIsValidToSave) {
  const struct {
    const char* plan;
    uint64_t seed;
  } runs[] = {{"3a977bda0c177c31c8c64e8076562d5a.json", 3},
              {"house_expo_room_1451.json", 5},
              {"house_expo_room_1451.json", 18},
              {"house_expo_room_0000.json", 1}};
  for (const auto& run : runs) {
    const sim::RobotDescription brick = *sim::robotByName("brick");
    const worlds::SiteLoad site = worlds::loadSite(kRoot + "houseexpo/" + run.plan, brick.cellCm);
    ASSERT_TRUE(site.site && site.site->start) << site.error;
    HouseConfig config;
    config.robot = brick;
    config.startPose = *site.site->start;
    config.startJitterDeg = 10;
    config.squareAtStart = true;  // as sim-house sets the brick up
    config.noise = *sim::noiseProfileByName("nxt");
    config.seed = run.seed;
    HouseMapper m(*site.site, config);
    m.run();
    std::string error;
    EXPECT_TRUE(m.network().validate(error)) << run.plan << " seed " << run.seed << ": " << error;
    for (const network::Gateway& g : m.network().gateways()) EXPECT_FALSE(g.cellsA.empty()) << run.plan;
  }
}

}  // namespace
}  // namespace nxtmap::house
