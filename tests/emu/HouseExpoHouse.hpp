// The HouseExpo house the emulated house tests map (house_expo_room_0000: three reachable plan rooms),
// loaded as `sim-house` and `emulate` load it (the plan's walls as drawn, the plan's own start, the
// published robot), and mapped once by sim-house on the same seed, noise (typical) and grid (the
// brick's 64 x 64) for the comparison. A house the console mapped is scored the same way: against the
// truth raster, from the same start cell, with the published sonar geometry.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/worlds/SiteFiles.hpp"

namespace nxtmap::emu::test {

struct HouseExpoHouse {
  // The noise seed: 1, or NXTMAP_HOUSE_SEED (1..1000) to measure another by hand.
  static uint64_t seed() {
    const char* v = std::getenv("NXTMAP_HOUSE_SEED");
    const long n = v ? std::strtol(v, nullptr, 10) : 1;
    return n >= 1 && n <= 1000 ? static_cast<uint64_t>(n) : 1;
  }
  static std::string path() { return std::string(NXTMAP_SOURCE_DIR) + "/worlds/houseexpo/house_expo_room_0000.json"; }

  sim::Site site;
  house::HousePlan plan;  // room boxes on the robot's grid
  sim::World truth;
  int col = 0, row = 0;  // the start cell in `truth`
  house::HouseScore sim;

  static house::HouseConfig simHouseConfig(const sim::Site& site) {
    house::HouseConfig c;
    c.robot = *sim::robotByName("published");
    c.startPose = *site.start;
    c.noise = *sim::noiseProfileByName("typical");
    c.seed = seed();
    return c;
  }

  static std::optional<HouseExpoHouse> load() {
    worlds::SiteLoad s = worlds::loadSite(path(), 10);
    house::HousePlanLoad p = house::loadHouseExpo(path());
    EXPECT_TRUE(s.site && s.site->start) << s.error;
    EXPECT_TRUE(p.plan) << p.error;
    if (!s.site || !s.site->start || !p.plan) return std::nullopt;
    house::HouseMapper m(*s.site, simHouseConfig(*s.site));
    HouseExpoHouse h{*s.site, *p.plan, m.world(), m.config().startCol, m.config().startRow, {}};
    EXPECT_TRUE(house::movePlanOntoGrid(h.plan, m.world(), m.robot().frame()));
    m.run();
    h.sim = house::scoreHouse(m);
    return h;
  }

  house::HouseInWorld inWorld(const network::HouseNetwork& mapped) const {
    return house::HouseInWorld{&mapped, &truth, mapping::FrameTransform(col, row, sim::Heading::N),
                               col,     row,    RangeGeometry{}};
  }

  // The house mapped whole, and as well as sim-house maps it up to the spread of the noise's draw
  // (see kDrawSpreadPct; both figures printed). Returns the score.
  house::HouseScore expectAHouse(const network::HouseNetwork& mapped, const char* what) const {
    const house::HouseScore s = house::scoreHouse(inWorld(mapped));
    const house::PlanCoverage c = house::planCoverage(inWorld(mapped), plan);
    std::printf(
        "%s: house_expo_room_0000, typical noise, seed %d: %.1f %% (%d rooms, %d gateways; plan rooms %d of %d "
        "mapped); sim-house %.1f %% (%d rooms, %d gateways)\n",
        what, int(seed()), s.agreementPct(), s.rooms, s.gateways, c.covered, c.reachable, sim.agreementPct(), sim.rooms,
        sim.gateways);
    EXPECT_GE(c.reachable, 3) << what << ": a house of at least three rooms";
    EXPECT_GE(s.rooms, 3) << what << ": at least three rooms mapped";
    EXPECT_EQ(c.covered, c.reachable) << what << ": every reachable plan room mapped to 90 % or more";
    EXPECT_GE(s.gateways, s.rooms - 1) << what << ": every room joined by a doorway passed";
    EXPECT_GE(s.agreementPct(), sim.agreementPct() - kDrawSpreadPct) << what << ": as well as sim-house";
    return s;
  }
  // The emulated robot draws its noise on its own timing (the firmware's readings and wheel steps,
  // not sim-house's; the console's timing moves it too), so the same seed is another draw of the same
  // noise. sim-house's own figure on this house at the brick's grid spread over 3.9 points from draw to
  // draw (90.2-94.1 % over seeds 1-24, typical noise) when this bound was set; since the rooms forget
  // what they saw beyond their exits on a full grid it spreads over 2.8 (91.4-94.2). The emulated
  // brick's draws spread wider and lower (89.3-93.8 % over seeds 1-10 and repeated seed-1 runs, the
  // room frames a cell or two apart): at this bound a draw fails now and then. The bound is left as
  // set, a known gap between the two, not loosened to fit it.
  static constexpr double kDrawSpreadPct = 3.9;
};

}  // namespace nxtmap::emu::test
