// The pilot in a scripted room: a rectangular room of straight walls (mm), wheels that err as told and ideal
// sonars; shared by the pilot's room tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap::pilotrig {

struct Rig {
  using Storage = ExplorerStorage<64, 64, 1024>;
  explicit Rig(const PilotConfig& c = PilotConfig{}, const ExplorerConfig& e = ExplorerConfig{})
      : config(e), pilot(explorer, c) {}
  std::unique_ptr<Storage> storage = std::make_unique<Storage>();
  MapLayers map{storage->map.view(), Storage::kWidth(), Storage::kHeight()};
  TravelPlanner planner{storage->travel.view(), Storage::kWidth(), Storage::kHeight()};
  ExplorerConfig config{};
  FrontierExplorer explorer{map, planner, config};
  Pilot pilot;
};

// Distance (mm) from (x, y) along heading a (rad, clockwise from North) to the walls of a box whose
// faces lie at x = west, east and y = south, north (mm).
inline double rangeToWalls(double west, double east, double south, double north, double x, double y, double a) {
  const double sx = std::sin(a), sy = std::cos(a);
  double best = 1e9;
  if (sx > 1e-9) best = std::min(best, (east - x) / sx);
  if (sx < -1e-9) best = std::min(best, (west - x) / sx);
  if (sy > 1e-9) best = std::min(best, (north - y) / sy);
  if (sy < -1e-9) best = std::min(best, (south - y) / sy);
  return best;
}

// How the scripted wheels err. Unseen by the encoders: each drive goes a random fraction within
// +-slipPerMille more or less than reported, each quarter turn ends a random angle within
// +-turnMrad off, each smaller rotation (steering, levelling) within +-smallTurnMrad; each echo
// comes back within +-rangeMm of the true distance. Seen: every drive stops shortMm before what was
// commanded; unseen, the drive numbered kickAfterDrive (1 = the first) ends kickEastMm further East.
// The random errors come from a fixed sequence, so every run is the same.
struct Wheels {
  int slipPerMille = 0;
  int turnMrad = 0;
  int smallTurnMrad = 0;
  int rangeMm = 0;
  int32_t shortMm = 0;
  int kickAfterDrive = 0;  // 0: none
  int32_t kickEastMm = 0;
  uint32_t seed = 12345;  // of the fixed sequence
  // What the robot's store says of its wheels (PilotConfig::wheels, which runInRoom sets from it): these wheels
  // have no systematic error, known to 0.1 deg/m and 0.1 % (a calibrated robot's store).
  WheelCalibration stored = calibrated();
  static WheelCalibration calibrated() {
    WheelCalibration w;
    w.driftVariance = 1745LL * 1745;
    w.turnVariance = 1000LL * 1000;
    return w;
  }
};

// Wheels and sonars that err everywhere (small rotations by up to 4 mrad, echoes by up to 17 mm), with
// the given slip and quarter-turn error; `run` picks the random sequence.
inline Wheels noisyWheels(int slipPerMille, int turnMrad, uint32_t run) {
  Wheels w;
  w.slipPerMille = slipPerMille;
  w.turnMrad = turnMrad;
  w.smallTurnMrad = 4;
  w.rangeMm = 17;
  w.seed = run * 7919;
  return w;
}

// A rectangular room of straight walls (mm, on cell faces or anywhere; the robot starts at the origin facing
// North, +y; cells of the explorer's geometry, 100 mm by default, centred on multiples of their edge). Ideal
// sonars: echoes within 1 m are good readings, farther ones up to 2.55 m come back as too far with their
// distance. Runs the pilot's explorer to the end.
struct RoomRun {
  double meanEstimateErrorMm =
      0;  // |true position - believed cell centre - tracker offset|, at the explorer's readings
  double meanHeadingErrorMrad = 0;  // |true heading - believed axis - tracker heading|, at the same readings
  double lateEstimateErrorMm = 0;   // meanEstimateErrorMm over the run's second half of readings
  int smallRotations = 0;           // rotations other than the explorer's quarter turns
  int readings = 0;
  int wrongCells = 0;  // cells of the finished map in the other state than the room's
};
inline RoomRun runInRoom(PilotConfig config, double west, double east, double south, double north, const Wheels& wheels,
                         const ExplorerConfig& explorer = ExplorerConfig{}) {
  config.wheels = wheels.stored;
  Rig rig(config, explorer);
  const double cell = explorer.geometry.cellCm * 10.0;  // mm
  uint32_t lcg = wheels.seed;
  const auto uniform = [&lcg](int amplitude) {  // -amplitude .. amplitude
    lcg = lcg * 1664525u + 1013904223u;
    return static_cast<int>((lcg >> 8) % static_cast<uint32_t>(2 * amplitude + 1)) - amplitude;
  };
  double x = 0, y = 0, h = 0;  // mm, mm, rad clockwise from North
  const auto rangeMm = [&](double a) { return rangeToWalls(west, east, south, north, x, y, a); };
  RoomRun out;
  double sum = 0, headingSum = 0;
  std::vector<double> errors;  // mm, at each reading
  int drives = 0;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  for (int i = 0; i < 400000 && !rig.pilot.finished(); ++i) {
    DriveEvent e = DriveEvent::thought();
    switch (a.kind) {
      case DriveAction::Kind::Read: {
        const Cell c = rig.explorer.pose().cell;
        const double bx = c.x * cell + rig.pilot.tracker().xMm(), by = c.y * cell + rig.pilot.tracker().yMm();
        sum += std::hypot(x - bx, y - by);
        errors.push_back(std::hypot(x - bx, y - by));
        const double axis = static_cast<int>(rig.explorer.pose().heading) * 1.5707963;
        headingSum += std::fabs(std::remainder(h - axis, 6.2831853) * 1000.0 - rig.pilot.tracker().thetaMrad());
        ++out.readings;
        const double mm =
            rangeMm(h + static_cast<int>(a.sensor) * 1.5707963) + (wheels.rangeMm > 0 ? uniform(wheels.rangeMm) : 0);
        RangeReading r;
        r.samples = 3;
        r.cm = static_cast<int16_t>(std::lround(mm / 10.0));
        r.status = mm <= 1000 ? RangeStatus::Good : (mm <= 2550 ? RangeStatus::TooFar : RangeStatus::NoEcho);
        if (r.status == RangeStatus::NoEcho) r.cm = 0;
        e = DriveEvent::range(a.sensor, r);
        break;
      }
      case DriveAction::Kind::Rotate: {
        const bool quarter = std::abs(a.value) > 700;
        const int amplitude = quarter ? wheels.turnMrad : wheels.smallTurnMrad;
        h += (a.value + (amplitude > 0 ? uniform(amplitude) : 0)) / 1000.0;
        out.smallRotations += quarter ? 0 : 1;
        e = DriveEvent::rotatedBy(a.value);
        break;
      }
      case DriveAction::Kind::Drive: {
        const int32_t s = wheels.shortMm;
        const int32_t done = a.value > s ? a.value - s : (a.value < -s ? a.value + s : 0);
        const double scale = 1.0 + (wheels.slipPerMille > 0 ? uniform(wheels.slipPerMille) : 0) / 1000.0;
        x += done * scale * std::sin(h);
        y += done * scale * std::cos(h);
        if (++drives == wheels.kickAfterDrive) x += wheels.kickEastMm;
        e = DriveEvent::drivenBy(done);
        break;
      }
      case DriveAction::Kind::Think:
      case DriveAction::Kind::Done: break;
    }
    a = rig.pilot.step(e);
  }
  EXPECT_TRUE(rig.pilot.finished());
  out.meanEstimateErrorMm = out.readings == 0 ? 0.0 : sum / out.readings;
  out.meanHeadingErrorMrad = out.readings == 0 ? 0.0 : headingSum / out.readings;
  const size_t half = errors.size() / 2;
  for (size_t i = half; i < errors.size(); ++i)
    out.lateEstimateErrorMm += errors[i] / static_cast<double>(errors.size() - half);
  for (int16_t cy = static_cast<int16_t>(south / cell - 2); cy <= north / cell + 2; ++cy) {
    for (int16_t cx = static_cast<int16_t>(west / cell - 2); cx <= east / cell + 2; ++cx) {
      const CellState st = rig.map.at(Cell{cx, cy});
      // Free when the whole cell lies inside the walls (a wall reaching a sliver into a cell blocks it).
      const bool inside = cx * cell - cell / 2 >= west && cx * cell + cell / 2 <= east &&
                          cy * cell - cell / 2 >= south && cy * cell + cell / 2 <= north;
      if ((st == CellState::Occupied && inside) || (st == CellState::Free && !inside)) ++out.wrongCells;
    }
  }
  return out;
}

}  // namespace nxtmap::pilotrig
