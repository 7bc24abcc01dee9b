#include "host/mapping/SimDrive.hpp"

#include "common/sensing/RangeFilter.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::mapping {

RangeGeometry sonarGeometryFor(const sim::World& world, double minRangeM, double rangeM, double beamHalfAngleDeg,
                               int mountCm) {
  RangeGeometry g;
  // A loaded world's cells are whole centimetres, World::kMinCellCm..kMaxCellCm (World::resolutionProblem),
  // so cellCm, a divisor in RangeGeometry, is never 0 and fits its int16_t.
  g.cellCm = static_cast<int16_t>(std::lround(world.resolutionM() * 100.0));
  g.minCm = static_cast<int16_t>(std::lround(minRangeM * 100.0));
  g.maxCm = static_cast<int16_t>(std::lround(rangeM * 100.0));
  g.mountCm = static_cast<int16_t>(mountCm);
  if (beamHalfAngleDeg > 0.0) {
    const double sure = 0.5 * g.cellCm / std::tan(beamHalfAngleDeg * 3.141592653589793 / 180.0) - g.mountCm;
    if (sure < g.maxCm) g.sureCm = static_cast<int16_t>(std::max(g.minCm + 1.0, std::floor(sure)));
  }
  return g;
}

int16_t sonarBlindCm(const sim::SonarNoise& sonar) {
  if (!(sonar.nearFieldCm > 0.0)) return 0;
  const double blind = sonar.nearFieldMode == sim::NearField::NoEcho ? sonar.nearFieldCm : sim::kNearFieldBlindCm;
  return static_cast<int16_t>(std::ceil(blind));
}

int16_t sonarConeMrad(const sim::SonarNoise& sonar) {
  const double deg = std::max(sonar.coneHalfAngleDeg, sonar.coneWideDeg);
  return static_cast<int16_t>(std::lround(std::clamp(deg, 0.0, 60.0) * 3.141592653589793 / 0.18));
}

WheelCalibration storedCalibration(const sim::WheelNoise& wheels) {
  // The floors: 0.1 deg/m of drift, 0.1 % of turn error (1 sigma).
  constexpr double kFloorUradPerM = 1745.0, kFloorPpm = 1000.0;
  const double drift =
      std::max(kFloorUradPerM, sim::driftDegPerMetre(wheels.diameterRatioError, sim::kNxtTrackCm) * 17453.29);
  const double turn = std::max(kFloorPpm, wheels.trackError * 1e6);
  WheelCalibration w;
  w.driftVariance = static_cast<int64_t>(std::llround(drift * drift));
  w.turnVariance = static_cast<int64_t>(std::llround(turn * turn));
  return w;
}

ExplorerConfig explorerConfigFor(const sim::World& world, const sim::RobotDescription& robot,
                                 const sim::SonarNoise& sonar, double minRangeM, double rangeM, double beamHalfAngleDeg,
                                 int blindCm, uint16_t searchSliceStates) {
  ExplorerConfig e;
  e.geometry = sonarGeometryFor(world, minRangeM, rangeM,
                                beamHalfAngleDeg >= 0.0 ? beamHalfAngleDeg : sonar.coneHalfAngleDeg, robot.mountCm);
  e.geometry.blindCm = blindCm >= 0 ? static_cast<int16_t>(blindCm) : sonarBlindCm(sonar);
  e.geometry.faceMarginCm = static_cast<int8_t>(robot.faceMarginCm);
  e.geometry.echoMarginCm = static_cast<int8_t>(robot.echoMarginCm);
  if (robot.correctsSonar) {
    e.geometry.scalePer10k = static_cast<int16_t>(std::lround(sonar.rangeScale * 10000.0));
    e.geometry.biasMm = static_cast<int16_t>(std::lround(sonar.biasCm * 10.0));
  }
  e.turnNeedsRoom = robot.turnNeedsRoom();
  e.searchSliceStates = searchSliceStates;
  return e;
}

DriveEvent carryOutOnRobot(sim::SimRobot& robot, const DriveAction& a, const RangeGeometry& geometry,
                           bool othersFiring) {
  switch (a.kind) {
    case DriveAction::Kind::Read: {
      RangeFilter filter(geometry);
      while (!filter.done()) filter.add(static_cast<uint8_t>(robot.ping(static_cast<int>(a.sensor), othersFiring)));
      return DriveEvent::range(a.sensor, filter.result());
    }
    case DriveAction::Kind::Rotate: {
      // Heard as the brick's drive layer reports it: the encoders' whole counts (a turn of 87 mrad is 10 motor
      // degrees, 87.3 mrad; the stalled part only when stalled). Wheels without encoders: as told.
      const bool done = robot.rotate(a.value * (180.0 / 3141.592653589793));
      if (robot.wheels().noise().encoderDeg > 0.0)
        return DriveEvent::rotatedBy(
            static_cast<int32_t>(std::lround(robot.lastSpinCountedDeg() * 3141.592653589793 / 180.0)));
      if (done) return DriveEvent::rotated();
      return DriveEvent::rotatedBy(static_cast<int32_t>(std::lround(a.value * robot.lastSpinShare())));
    }
    case DriveAction::Kind::Drive: return DriveEvent::driven(!robot.drive(a.value / 10.0));
    case DriveAction::Kind::Think: return DriveEvent::thought();
    case DriveAction::Kind::Done: break;
  }
  return DriveEvent::start();
}

}  // namespace nxtmap::mapping
