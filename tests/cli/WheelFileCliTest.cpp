// `nxtmap sim --wheels FILE`: a robot keeps what it learnt of its wheels from run to run, as the brick does. The
// first run (no file) starts with nothing stored and writes what it learnt; the next reads it; a bad file is one
// line, exit code 2, and is left as it was.
#include "tests/cli/CliTestSupport.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "host/cli/WheelFile.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kRun =
    "sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --robot brick --noise nxt-uncalibrated "
    "--start-jitter 10 --seed 3 --show none --wheels ";

TEST(WheelFileCli, TheFirstRunWritesWhatItLearntAndTheNextStartsWithIt) {
  TempDir t("wheels");
  const std::string file = t.path("wheels.yaml");
  const RunOutput first = runCli(kRun + shellQuote(file));
  ASSERT_EQ(first.exitCode, 0) << first.err;
  EXPECT_EQ(first.out.find("wheels stored"), std::string::npos) << first.out;
  std::string error;
  const std::optional<WheelCalibration> learnt = readWheelFile(file, error);
  ASSERT_TRUE(learnt) << error;
  // nxt-uncalibrated: 2 deg/m (34,907 urad/m) of drift and turns 2 % off; one run learns them to a few tenths.
  EXPECT_GT(std::abs(learnt->driftUradPerM), 20000);
  EXPECT_GT(std::abs(learnt->turnPpm), 15000);

  const RunOutput second = runCli(kRun + shellQuote(file));
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_NE(second.out.find("wheels stored    read from " + file), std::string::npos) << second.out;
  const std::optional<WheelCalibration> again = readWheelFile(file, error);
  ASSERT_TRUE(again) << error;
  EXPECT_LE(again->driftVariance, learnt->driftVariance);  // a second run is at least as sure
}

TEST(WheelFileCli, TheFileRoundTripsAndItsRangesAreChecked) {
  WheelCalibration w;
  w.driftUradPerM = -34000;
  w.driftVariance = 3100LL * 3100;
  w.turnPpm = 19500;
  w.turnVariance = 1800LL * 1800;
  TempDir t("wheels_table");
  const std::string good = t.path("good.yaml");
  std::ofstream(good) << wheelFileText(w);
  std::string error;
  const std::optional<WheelCalibration> back = readWheelFile(good, error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->driftUradPerM, -34000);
  EXPECT_EQ(back->driftVariance, 3100LL * 3100);
  EXPECT_EQ(back->turnPpm, 19500);
  EXPECT_EQ(back->turnVariance, 1800LL * 1800);
  EXPECT_FALSE(readWheelFile(t.path("none.yaml"), error));
  EXPECT_TRUE(error.empty()) << "a missing file is nothing stored, not an error: " << error;
}

TEST(WheelFileCli, ABadFileIsOneLineExitTwoAndLeftAsItWas) {
  struct Case {
    const char* name;
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"not yaml", "drift_urad_per_m: [1,\n", "not a wheels file"},
      {"a list", "- 1\n- 2\n", "not a wheels file"},
      {"a word", "drift_urad_per_m: x\n", "drift_urad_per_m must be a whole number"},
      {"a missing field", "drift_urad_per_m: 0\ndrift_sigma_urad_per_m: 5\nturn_ppm: 0\n",
       "turn_sigma_ppm must be a whole number"},
      {"turns 30 % off", "drift_urad_per_m: 0\ndrift_sigma_urad_per_m: 5\nturn_ppm: 300000\nturn_sigma_ppm: 4\n",
       "turn_ppm must lie in -99999..99999"},
      {"a sigma of 0", "drift_urad_per_m: 0\ndrift_sigma_urad_per_m: 0\nturn_ppm: 0\nturn_sigma_ppm: 4\n",
       "drift_sigma_urad_per_m must lie in 1..1000000"},
  };
  for (const Case& c : cases) {
    TempDir t("wheels_bad");
    const std::string file = t.path("bad.yaml");
    std::ofstream(file) << c.text;
    const RunOutput r = runCli(kRun + shellQuote(file));
    EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.out << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(lines(r.err).size(), 1u) << c.name << ": " << r.err;
    EXPECT_EQ(readFile(file), c.text) << c.name;
  }
}

// What `sim` and `sim-house` print of the start's turn calibration, one line whatever it found.
TEST(WheelFileText, TheTurnCalibrationIsOneLineWhateverItFound) {
  struct Row {
    bool found;
    int32_t errorPpm;
    bool unasked, turnedBack;
    const char* text;
  };
  const Row rows[] = {
      {true, 20700, false, false, "turns +2.07 % off (4 whole turns between two sweeps): every turn corrected by it"},
      {true, -4800, true, false,
       "turns -0.48 % off (4 whole turns between two sweeps): every turn corrected by it (unasked: nothing was known "
       "of the turns)"},
      {false, 0, false, false, "no straight wall in range: turns not corrected"},
      {false, 0, true, true,
       "the second sweep lost the walls the first found: the 4 whole turns turned back, turns not corrected "
       "(unasked: nothing was known of the turns)"},
  };
  for (const Row& row : rows)
    EXPECT_EQ(turnCalibrationText(row.found, row.errorPpm, 4, row.unasked, row.turnedBack), row.text);
}

}  // namespace
}  // namespace nxtmap::cli::test
