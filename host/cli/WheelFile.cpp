#include "host/cli/WheelFile.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>

#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

// A whole number within [lo, hi] under `key`; false with `error` set otherwise.
bool field(const YAML::Node& root, const std::string& path, const char* key, int64_t lo, int64_t hi, int64_t& out,
           std::string& error) {
  const YAML::Node n = root[key];
  try {
    if (!n || !n.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "missing");
    out = n.as<int64_t>();
  } catch (const YAML::Exception&) {
    error = path + ": " + key + " must be a whole number";
    return false;
  }
  if (out < lo || out > hi) {
    error = path + ": " + key + " must lie in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " +
            std::to_string(out);
    return false;
  }
  return true;
}

int64_t sigmaOf(int64_t variance) {
  const auto s = static_cast<int64_t>(std::ceil(std::sqrt(static_cast<double>(variance))));
  return s < 1 ? 1 : s;
}

}  // namespace

std::optional<WheelCalibration> readWheelFile(const std::string& path, std::string& error) {
  error.clear();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    error = path + ": not a wheels file (" + e.msg + ")";
    return std::nullopt;
  }
  if (!root.IsMap()) {
    error = path + ": not a wheels file (a YAML map of four numbers expected)";
    return std::nullopt;
  }
  int64_t drift = 0, driftSigma = 0, turn = 0, turnSigma = 0;
  if (!field(root, path, "drift_urad_per_m", -199999, 199999, drift, error) ||
      !field(root, path, "drift_sigma_urad_per_m", 1, 1000000, driftSigma, error) ||
      !field(root, path, "turn_ppm", -99999, 99999, turn, error) ||
      !field(root, path, "turn_sigma_ppm", 1, 1000000, turnSigma, error))
    return std::nullopt;
  WheelCalibration w;
  w.driftUradPerM = static_cast<int32_t>(drift);
  w.driftVariance = driftSigma * driftSigma;
  w.turnPpm = static_cast<int32_t>(turn);
  w.turnVariance = turnSigma * turnSigma;
  return w;
}

std::string wheelFileText(const WheelCalibration& w) {
  std::ostringstream out;
  out << "# what the robot learnt of its wheels (nxtmap sim --wheels): read at a run's start, written at its end\n"
      << "drift_urad_per_m: " << w.driftUradPerM << "  # heading change per metre driven forward, + clockwise\n"
      << "drift_sigma_urad_per_m: " << sigmaOf(w.driftVariance) << "\n"
      << "turn_ppm: " << w.turnPpm << "  # turns' error: actual / commanded - 1, + too far\n"
      << "turn_sigma_ppm: " << sigmaOf(w.turnVariance) << "\n";
  return out.str();
}

std::string wheelsLearntText(const WheelCalibration& w, const sim::WheelModel& truth) {
  const auto signedNum = [](double v, int digits) { return (v >= 0 ? "+" : "") + report::formatNumber(v, digits); };
  const double degPerRad = 180.0 / 3.141592653589793;
  std::ostringstream out;
  out << "drift " << signedNum(w.driftUradPerM * 1e-6 * degPerRad, 2) << " deg/m (+-"
      << report::formatNumber(std::sqrt(static_cast<double>(w.driftVariance)) * 1e-6 * degPerRad, 2) << ", true "
      << signedNum(truth.systematicDriftRadPerM() * degPerRad, 2) << "), turns " << signedNum(w.turnPpm / 1e4, 2)
      << " % (+-" << report::formatNumber(std::sqrt(static_cast<double>(w.turnVariance)) / 1e4, 2) << ", true "
      << signedNum(truth.systematicTurnError() * 100.0, 2) << ")";
  return out.str();
}

std::string turnCalibrationText(bool found, int32_t errorPpm, int turns, bool unasked, bool turnedBack) {
  std::ostringstream out;
  if (!found && turnedBack) {
    out << "the second sweep lost the walls the first found: the " << turns
        << " whole turns turned back, turns not corrected";
  } else if (!found) {
    out << "no straight wall in range: turns not corrected";
  } else {
    out << "turns " << (errorPpm >= 0 ? "+" : "") << report::formatNumber(errorPpm / 10000.0, 2) << " % off (" << turns
        << " whole turns between two sweeps): every turn corrected by it";
  }
  if (unasked) out << " (unasked: nothing was known of the turns)";
  return out.str();
}

}  // namespace nxtmap::cli
