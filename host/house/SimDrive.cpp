#include "host/house/SimDrive.hpp"

#include "common/sensing/RangeFilter.hpp"

namespace nxtmap::house {

DriveEvent carryOutOnRobot(sim::SimRobot& robot, const DriveAction& a, const RangeGeometry& geometry) {
  switch (a.kind) {
    case DriveAction::Kind::Read: {
      RangeFilter filter(geometry);
      while (!filter.done()) filter.add(static_cast<uint8_t>(robot.ping(static_cast<int>(a.sensor))));
      return DriveEvent::range(a.sensor, filter.result());
    }
    case DriveAction::Kind::Rotate:
      robot.rotate(a.value * (180.0 / 3141.592653589793));
      return DriveEvent::rotated();
    case DriveAction::Kind::Drive:
      return DriveEvent::driven(!robot.drive(a.value / 10.0));
    case DriveAction::Kind::Think:
      return DriveEvent::thought();
    case DriveAction::Kind::Done:
      break;
  }
  return DriveEvent::start();
}

}  // namespace nxtmap::house
