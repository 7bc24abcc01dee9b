// The pilot against scripted wheels and sensors: every explorer reading is taken on the axis
// the explorer marks it along, even when a turn ended off its target (as the brick's encoders
// report it) or a move was steered towards a cell centre.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {
namespace {

struct Rig {
  using Storage = ExplorerStorage<64, 64, 1024>;
  std::unique_ptr<Storage> storage = std::make_unique<Storage>();
  MapLayers map{storage->map.view(), Storage::kWidth(), Storage::kHeight()};
  TravelPlanner planner{storage->travel.view(), Storage::kWidth(), Storage::kHeight()};
  ExplorerConfig config{};
  FrontierExplorer explorer{map, planner, config};
  Pilot pilot{explorer, PilotConfig{}};
};

// Distance in mrad from `urad` (microradians) to the nearest multiple of a quarter turn.
int32_t offAxisMrad(int64_t urad) {
  const int64_t q = 1570796;
  int64_t r = urad % q;
  if (r < 0) r += q;
  if (r > q / 2) r -= q;
  return static_cast<int32_t>((r < 0 ? -r : r) / 1000);
}

TEST(Pilot, LevelsAKnownHeadingErrorBeforeEachExplorerReading) {
  Rig rig;
  // Open space, nothing in range. As the encoders report it: every turn of a quarter or more
  // ends 35 mrad past its target, every drive 6 mm short (so after a turn the next move steers
  // towards the cell centre beside it); small rotations are exact.
  int64_t headingUrad = 0;  // the robot's real heading, + clockwise
  int readsChecked = 0, errorsMade = 0;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  for (int i = 0; i < 3000 && !rig.pilot.finished(); ++i) {
    DriveEvent e = DriveEvent::thought();
    switch (a.kind) {
      case DriveAction::Kind::Read: {
        EXPECT_LE(offAxisMrad(headingUrad), PilotConfig{}.minRotateMrad) << "reading " << readsChecked;
        ++readsChecked;
        RangeReading r;
        r.status = RangeStatus::TooFar;
        r.samples = 1;
        e = DriveEvent::range(a.sensor, r);
        break;
      }
      case DriveAction::Kind::Rotate: {
        const bool quarter = std::abs(a.value) > 700;
        const int32_t achieved = a.value + (quarter ? 35 : 0);
        errorsMade += quarter ? 1 : 0;
        headingUrad += static_cast<int64_t>(achieved) * 1000;
        e = DriveEvent::rotatedBy(achieved);
        break;
      }
      case DriveAction::Kind::Drive:
        e = DriveEvent::drivenBy(a.value > 0 ? a.value - 6 : a.value + 6);
        break;
      case DriveAction::Kind::Think:
      case DriveAction::Kind::Done:
        break;
    }
    a = rig.pilot.step(e);
  }
  EXPECT_GT(errorsMade, 2);  // the script did turn the robot off its axis
  EXPECT_GT(readsChecked, 20);
}

}  // namespace
}  // namespace nxtmap
