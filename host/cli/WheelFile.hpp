// WheelFile: what a simulated robot keeps of its wheels between runs, as the brick keeps its pilot's learnt
// WheelCalibration: a small YAML file (`nxtmap sim --wheels FILE`), read at a run's start and written at its end.
//
//   drift_urad_per_m: -34000     # heading change per metre driven forward, + clockwise (|.| < 200000)
//   drift_sigma_urad_per_m: 3100 # 1 sigma (1..1000000)
//   turn_ppm: 19500              # turns' error, actual / commanded - 1, + too far (|.| < 100000)
//   turn_sigma_ppm: 1800         # 1 sigma (1..1000000)
#pragma once

#include <optional>
#include <string>

#include "common/motion/PoseTracker.hpp"
#include "host/sim/WheelModel.hpp"

namespace nxtmap::cli {

// The file's wheels; nullopt with `error` empty when the file does not exist, and with `error` set (naming the
// file and the field) when it cannot be read or holds anything outside the ranges above.
std::optional<WheelCalibration> readWheelFile(const std::string& path, std::string& error);

// The file's text for `w` (variances written as their square roots, rounded up to at least 1).
std::string wheelFileText(const WheelCalibration& w);

// "drift +1.98 deg/m (+-0.17, true +2.04), turns +1.9 % (+-0.15, true +2.04)": what a simulated robot learnt of
// its wheels beside the simulated truth, as `sim` and `sim-house` print it.
std::string wheelsLearntText(const WheelCalibration& w, const sim::WheelModel& truth);

// "turns +2.07 % off (4 whole turns between two sweeps): every turn corrected by it", "no straight wall in
// range: turns not corrected" or (`turnedBack`, TurnCalibration::turnedBack) that the second sweep lost the walls,
// and " (unasked: ...)" when `unasked`: what a start's turn calibration measured.
std::string turnCalibrationText(bool found, int32_t errorPpm, int turns, bool unasked, bool turnedBack = false);

}  // namespace nxtmap::cli
