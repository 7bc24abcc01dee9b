// `explore house` end to end on the stand-in brick: the console's HouseExploration (the PC's house
// planner over the link) and the brick's house commands (HouseBrick in SimBrick) joined by the
// link harness at the NXT's baud rate, on a HouseExpo plan with typical noise. Clean, and with 5 %
// damaged bytes and a forced disconnect in the middle of the house: every reachable room mapped,
// every doorway passed a gateway, no room started twice, no command run twice; the house scored
// against the world beside `sim-house` on the same plan, seed and noise: the console's planner,
// with standing scans and the start anchor over the link, decides as sim-house's and makes its house.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "host/console/HouseExploration.hpp"
#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/link/LinkHarness.hpp"

namespace nxtmap::console {
namespace {

const std::string kPlan = std::string(NXTMAP_SOURCE_DIR) + "/worlds/houseexpo/house_expo_room_0000.json";
constexpr uint64_t kSeed = 3;
constexpr int kGridCells = 128;  // the published robot's 10 cm cells: these rooms need more than 64

struct Plan {
  house::HousePlan plan;
  int col = 0, row = 0;
};

Plan loadPlan() {
  const house::HousePlanLoad l = house::loadHouseExpo(kPlan);
  EXPECT_TRUE(l.plan) << l.error;
  Plan p{*l.plan};
  EXPECT_TRUE(house::defaultStart(p.plan, p.col, p.row));
  return p;
}

link::SimBrickConfig brickConfig(const Plan& p, uint64_t seed) {
  link::SimBrickConfig c;
  c.run.startCol = p.col;
  c.run.startRow = p.row;
  c.run.noise = *sim::noiseProfileByName("typical");
  c.run.seed = seed;
  c.run.strategy = Strategy::Frontier;
  c.run.grid = *mapping::GridCapacity::ofCells(kGridCells);
  c.actionMs = 5;
  c.cellMs = 10;
  return c;
}

// What the house planner decided, beside the house it made.
struct Decisions {
  int exitsFound = 0, exitsUnreached = 0, relocalisations = 0, openingsTried = 0;
  template <class P>
  static Decisions of(const P& planner) {
    return Decisions{planner.exitsFound(), planner.exitsUnreached(), planner.relocalisations(),
                     planner.openingsTried()};
  }
};

struct SimHouse {
  house::HouseScore score;
  Decisions decisions;
};

// sim-house on the same plan, start, seed and noise.
SimHouse simHouse(const Plan& p, uint64_t seed) {
  house::HouseConfig c;
  c.startCol = p.col;
  c.startRow = p.row;
  c.noise = *sim::noiseProfileByName("typical");
  c.seed = seed;
  c.grid = *mapping::GridCapacity::ofCells(kGridCells);
  house::HouseMapper m(p.plan.world, c);
  m.run();
  return SimHouse{house::scoreHouse(m), Decisions::of(m)};
}

struct Outcome {
  house::HouseScore score;
  house::PlanCoverage coverage;
  Decisions decisions;
  int roomsStarted = 0, roomsMapped = 0;
  bool noRepeats = false;
  uint32_t atMs = 0;
};

// Maps the plan's house from the console over the harness; `faults`: 5 % damaged bytes each way and
// a 3 s disconnect while the brick maps the second room.
Outcome mapOverLink(const Plan& p, uint64_t seed, bool faults) {
  link::SimBrick brick(p.plan.world, brickConfig(p, seed));
  link::Session pc(link::SessionConfig{0x40E5E000u + (faults ? 1u : 0u), 250, 250});
  link::HarnessConfig hc;
  if (faults) {
    hc.toPc = link::LossConfig::fivePercent(11);
    hc.toBrick = link::LossConfig::fivePercent(12);
  }
  link::LinkHarness h(brick, pc, hc);
  Outcome o;
  EXPECT_TRUE(h.runUntil([&] { return pc.connected() && pc.status().has_value(); }, 30000));
  HouseExploration x;  // the brick's sensing, from its HelloReply
  x.start(pc, 0.0);
  bool disconnected = !faults;
  const bool done = h.runUntil(
      [&] {
        const std::string said = x.poll(pc, h.nowMs() / 1000.0);
        if (!said.empty()) std::printf("%u ms: %s", h.nowMs(), said.c_str());  // the console's progress lines
        if (!disconnected && brick.house().session().roomsStarted() >= 2) {    // mapping the second room
          disconnected = true;
          h.disconnect(3000);
        }
        return x.done();
      },
      4 * 3600 * 1000);
  EXPECT_TRUE(done) << x.progress();
  EXPECT_TRUE(disconnected);
  const house::HouseInWorld in{&x.planner().network(),
                               &brick.world(),
                               mapping::FrameTransform(p.col, p.row, sim::Heading::N),
                               p.col,
                               p.row,
                               brick.explorerConfig().geometry};
  o.score = house::scoreHouse(in);
  o.coverage = house::planCoverage(in, p.plan);
  o.decisions = Decisions::of(x.planner());
  o.roomsStarted = brick.house().session().roomsStarted();
  o.roomsMapped = x.roomsMapped();
  o.noRepeats = std::set<uint16_t>(brick.executed().begin(), brick.executed().end()).size() == brick.executed().size();
  o.atMs = h.nowMs();
  return o;
}

void expectWholeHouse(const Outcome& o, const std::string& what) {
  EXPECT_GE(o.coverage.reachable, 3) << what << ": a house of at least three rooms";
  EXPECT_EQ(o.coverage.covered, o.coverage.reachable) << what << ": every reachable plan room mapped";
  EXPECT_GE(o.score.gateways, o.roomsStarted - 1) << what << ": every doorway passed is a gateway";
  EXPECT_EQ(o.roomsStarted, o.roomsMapped) << what << ": no room started twice";
  EXPECT_TRUE(o.noRepeats) << what << ": no command run twice";
  EXPECT_GE(o.score.agreementPct(), 90.0) << what;  // a floor; the comparison with sim-house is printed
}

// The console's planner decided as sim-house's (standing scans, the start anchor, exits, openings)
// and made its house cell for cell.
void expectSameAsSimHouse(const Outcome& o, const SimHouse& sim, const std::string& what) {
  EXPECT_EQ(o.decisions.exitsFound, sim.decisions.exitsFound) << what;
  EXPECT_EQ(o.decisions.exitsUnreached, sim.decisions.exitsUnreached) << what;
  EXPECT_EQ(o.decisions.relocalisations, sim.decisions.relocalisations)
      << what << ": standing scans that moved the belief";
  EXPECT_EQ(o.decisions.openingsTried, sim.decisions.openingsTried) << what;
  EXPECT_EQ(o.score.agree, sim.score.agree) << what;
  EXPECT_EQ(o.score.wrong, sim.score.wrong) << what;
  EXPECT_EQ(o.score.rooms, sim.score.rooms) << what;
  EXPECT_EQ(o.score.gateways, sim.score.gateways) << what;
  EXPECT_GE(o.score.agreementPct(), sim.score.agreementPct()) << what;
}

// Seeds 1-3: the clean link, the damaged link with a disconnect (the same house: nothing lost), and
// sim-house on the same plan, seed and noise (the same decisions, the same house).
TEST(HouseExploration, TheConsoleMapsAHouseExpoHouseThroughTheStandInBrickAndADamagedLinkLosesNothing) {
  const Plan p = loadPlan();
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const SimHouse simRun = simHouse(p, seed);
    const house::HouseScore& sim = simRun.score;
    const Outcome clean = mapOverLink(p, seed, false);
    const Outcome lossy = mapOverLink(p, seed, true);
    std::printf(
        "house_expo_room_0000, typical noise, seed %d: console %.1f %% (%d rooms, %d gateways, %u ms); "
        "with 5 %% damaged bytes and a disconnect %.1f %% (%u ms); sim-house %.1f %% (%d rooms, %d gateways); "
        "beliefs moved by a scan %d (sim-house %d)\n",
        int(seed), clean.score.agreementPct(), clean.score.rooms, clean.score.gateways, clean.atMs,
        lossy.score.agreementPct(), lossy.atMs, sim.agreementPct(), sim.rooms, sim.gateways,
        clean.decisions.relocalisations, simRun.decisions.relocalisations);
    const std::string s = "seed " + std::to_string(seed);
    expectWholeHouse(clean, s + ", clean link");
    expectWholeHouse(lossy, s + ", damaged link");
    EXPECT_EQ(lossy.score.agree, clean.score.agree) << s << ": the damaged link's house is the clean link's";
    EXPECT_EQ(lossy.score.wrong, clean.score.wrong) << s;
    EXPECT_EQ(lossy.score.rooms, clean.score.rooms) << s;
    EXPECT_EQ(lossy.score.gateways, clean.score.gateways) << s;
    expectSameAsSimHouse(clean, simRun, s + ", clean link");
  }
}

// A standing scan over the damaged link: the Scan runs once, and the readings the PC gets are the
// brick's, with the pose it stood at.
TEST(HouseExploration, AStandingScanOverADamagedLinkIsTheBricksOwnAndRunsOnce) {
  const Plan p = loadPlan();
  link::SimBrick brick(p.plan.world, brickConfig(p, 1));
  link::Session pc(link::SessionConfig{0x5CA17u, 250, 250});
  link::HarnessConfig hc;
  hc.toPc = link::LossConfig::fivePercent(21);
  hc.toBrick = link::LossConfig::fivePercent(22);
  link::LinkHarness h(brick, pc, hc);
  ASSERT_TRUE(h.runUntil([&] { return pc.connected() && pc.status().has_value(); }, 30000));
  pc.explore(protocol::ExploreMsg{protocol::ExploreStrategy::Frontier, true});
  const auto roomOver = [&] {
    return pc.roomExits() && pc.roomExits()->roomId == 1 && pc.roomExits()->end != ExplorerEnd::Running &&
           pc.readings().has_value();
  };
  ASSERT_TRUE(h.runUntil(roomOver, 3600 * 1000));
  const RoomSession& session = brick.house().session();
  for (const uint16_t id : {uint16_t{1}, uint16_t{2}}) {
    pc.scan(id);
    ASSERT_TRUE(h.runUntil([&] { return pc.readings()->scanId == id; }, 600 * 1000)) << id;
    EXPECT_EQ(session.outcome(), RoomSession::Outcome::Scanned) << id;
    EXPECT_EQ(pc.readings()->scanPose.cell, session.pose().cell) << id;
    EXPECT_EQ(pc.readings()->scanPose.heading, session.pose().heading) << id;
    for (int i = 0; i < kSensorCount; ++i) {
      const RangeReading& b = session.scanReading(static_cast<Sensor>(i));
      EXPECT_EQ(pc.readings()->scan[i].status, b.status) << id << ", sensor " << i;
      EXPECT_EQ(pc.readings()->scan[i].cm, b.cm) << id << ", sensor " << i;
      EXPECT_EQ(pc.readings()->scan[i].samples, b.samples) << id << ", sensor " << i;
    }
  }
  EXPECT_TRUE(h.runUntil([&] { return pc.commandsDone(); }, 60 * 1000));
  EXPECT_EQ(brick.executed().size(), 3u) << "explore, scan, scan: each once";
  EXPECT_GT(pc.counters().commandRetries + pc.decoderCounters().skipped, 0u) << "the link did damage";
}

}  // namespace
}  // namespace nxtmap::console
