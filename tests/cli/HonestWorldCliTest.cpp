// The honest world from the outside (issue 16): hand-made world files, the robot descriptions, the start
// jitter, the presets and the start's calibration through `nxtmap sim`, `experiments` and `emulate`; bad worlds
// and options are one line and exit code 2.
#include "tests/cli/CliTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nxtmap::cli::test {
namespace {

const std::string kTurned = "worlds/rooms/square-turned.yaml";  // 3 x 3 m, turned 10 deg, a third of a cell off
const std::string kLiving = "worlds/rooms/living-room.yaml";
const std::string kHouse = "worlds/houseexpo/house_expo_room_0000.json";

void expectUsageError(const RunOutput& r, const std::string& needle) {
  EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("nxtmap: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
}

std::string field(const std::string& out, const std::string& label) {
  const size_t at = out.find("\n" + label);
  if (at == std::string::npos) return "";
  return out.substr(at + 1, out.find('\n', at + 1) - at - 1);
}

TEST(HonestWorldCli, ATurnedAndOffsetRoomLoadsRunsAndIsScoredInBothFrames) {
  const RunOutput r = runCli("sim " + kTurned + " --robot brick --noise nxt --start-jitter 10 --show none");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("cells of 20 cm, robot brick"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("deg off square)"), std::string::npos) << r.out;
  for (const std::string label : {"detected", "wrong cells", "unsafe free", "phantom occupied", "lost", "aligned"})
    EXPECT_FALSE(field(r.out, label).empty()) << label << "\n" << r.out;
  EXPECT_NE(field(r.out, "aligned").find("to fit the world best: detected"), std::string::npos) << r.out;
}

TEST(HonestWorldCli, TheBrickTurnsSquareToTheWallsFirstThePublishedRobotOnlyWhenAsked) {
  const std::string run = "sim " + kTurned + " --start-jitter 10 --show none --seed 2";
  const RunOutput brick = runCli(run + " --robot brick --noise nxt");
  ASSERT_EQ(brick.exitCode, 0) << brick.err;
  EXPECT_EQ(field(brick.out, "square").rfind("square ", 0), 0u) << brick.out;
  const RunOutput published = runCli(run + " --noise typical");
  ASSERT_EQ(published.exitCode, 0) << published.err;
  EXPECT_EQ(field(published.out, "square"), "") << published.out;
  const RunOutput asked = runCli(run + " --noise typical --square yes");
  ASSERT_EQ(asked.exitCode, 0) << asked.err;
  // The room is turned 10 degrees, the robot set down off it: the sweep finds the walls and turns onto them.
  EXPECT_NE(field(asked.out, "square").find("turned square: left "), std::string::npos) << asked.out;
  EXPECT_NE(field(asked.out, "square").find("deg off the start heading"), std::string::npos) << asked.out;
}

// The "calibrated" line of `out`: none when `calibrated` is empty, else one holding `always` and `calibrated`.
void expectCalibratedLine(const std::string& out, const std::string& always, const std::string& calibrated,
                          const std::string& args) {
  const std::string line = field(out, "calibrated");
  if (calibrated.empty()) {
    EXPECT_EQ(line, "") << args;
    return;
  }
  EXPECT_NE(line.find(always), std::string::npos) << args << "\n" << out;
  EXPECT_NE(line.find(calibrated), std::string::npos) << args << "\n" << out;
}

// --calibrate: a robot that knows nothing of its turns (nxt-uncalibrated: nothing stored) measures them unasked, as
// the brick does; a calibrated one (nxt) only when asked; =no never.
TEST(HonestWorldCli, TheBrickMeasuresItsTurnsFirstWhenItKnowsNothingOfThem) {
  const std::string run = "sim " + kTurned + " --robot brick --start-jitter 10 --show none --seed 2 --noise ";
  struct Row {
    std::string args, calibrated;  // what the "calibrated" line says ("": no such line)
  };
  const Row rows[] = {
      {"nxt-uncalibrated", "(unasked: nothing was known of the turns)"},
      {"nxt-uncalibrated --calibrate=auto", "(unasked: nothing was known of the turns)"},
      {"nxt-uncalibrated --calibrate=no", ""},
      {"nxt", ""},
      {"nxt --calibrate", "every turn corrected by it"},
  };
  for (const Row& row : rows) {
    const RunOutput r = runCli(run + row.args);
    ASSERT_EQ(r.exitCode, 0) << row.args << ": " << r.err;
    expectCalibratedLine(r.out, "whole turns between two sweeps", row.calibrated, row.args);
  }
  const RunOutput asked = runCli(run + "nxt --calibrate");
  EXPECT_EQ(field(asked.out, "calibrated").find("unasked"), std::string::npos) << asked.out;
}

// sim-house --calibrate: the first room measures the turns as `sim` does (the brick's house mode does too); every
// house says what its runs learnt of the wheels beside the truth.
TEST(HonestWorldCli, TheHousesFirstRoomMeasuresTheTurnsAsTheBrickDoes) {
  const std::string run = "sim-house " + kHouse + " --robot brick --start-jitter 10 --seed 1 --noise ";
  struct Row {
    std::string args, calibrated;  // what the "calibrated" line says ("": no such line)
    std::string trueTurns;         // the simulated robot's, in the "wheels learnt" line
  };
  const Row rows[] = {
      {"nxt-uncalibrated", "(unasked: nothing was known of the turns)", "true +2.04)"},
      {"nxt-uncalibrated --calibrate=no", "", "true +2.04)"},
      {"nxt", "", "true +0.5)"},
      {"nxt --calibrate", "every turn corrected by it", "true +0.5)"},
  };
  for (const Row& row : rows) {
    const RunOutput r = runCli(run + row.args);
    ASSERT_EQ(r.exitCode, 0) << row.args << ": " << r.err;
    expectCalibratedLine(r.out, "first room: turns ", row.calibrated, row.args);
    const std::string wheels = field(r.out, "wheels learnt");
    EXPECT_NE(wheels.find("turns "), std::string::npos) << row.args << "\n" << r.out;
    EXPECT_NE(wheels.find(row.trueTurns), std::string::npos) << row.args << "\n" << r.out;
  }
  EXPECT_EQ(field(runCli(run + "nxt --calibrate").out, "calibrated").find("unasked"), std::string::npos);
}

TEST(HonestWorldCli, SameSeedSameRunAnotherSeedAnotherStart) {
  const std::string run = "sim " + kLiving + " --robot brick --noise nxt --start-jitter 10 --show none --seed ";
  const RunOutput a = runCli(run + "4"), b = runCli(run + "4"), c = runCli(run + "5");
  ASSERT_EQ(a.exitCode, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(field(a.out, "run"), field(c.out, "run"));  // set down at another angle
}

TEST(HonestWorldCli, NoiseListPrintsEveryPresetWithUnits) {
  const RunOutput r = runCli("sim --noise list");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const std::string preset : {"typical:", "nxt:", "nxt-uncalibrated:", "harsh:"})
    EXPECT_NE(r.out.find("\n" + preset + "\n"), std::string::npos) << preset;
  for (const std::string unit : {" cm ", " deg ", " ms "}) EXPECT_NE(r.out.find(unit), std::string::npos) << unit;
  EXPECT_EQ(r.out.rfind("ideal:", 0), 0u) << r.out;
}

TEST(HonestWorldCli, ExperimentsRunTheLayoutsAtTheBricksCells) {
  TempDir tmp("brick_layouts");
  const RunOutput r = runCli("experiments worlds/seed-appendix-a --robot brick --noise nxt --start-jitter 3 --csv " +
                             tmp.path("r.csv"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The brick sweeps square first: each run that found the walls says how far off them it was left.
  EXPECT_NE(r.out.find(" of 18 runs: left "), std::string::npos) << r.out;
  const std::vector<std::string> rows = lines(readFile(tmp.path("r.csv")));  // one seed: each row is one run
  ASSERT_EQ(rows.size(), 19u);
  int squared = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::string last = rows[i].substr(rows[i].rfind(',') + 1);
    if (last.empty()) continue;
    ++squared;
    EXPECT_LT(std::fabs(std::stod(last)), 10.0) << rows[i];  // 3 deg jitter: square to within a few degrees
  }
  EXPECT_GE(squared, 15) << "the 18 layouts' walls are in reach of the sweep";
  EXPECT_NE(r.out.find("robot brick (20 cm cells), set down up to 3 deg off square"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("noise nxt"), std::string::npos) << r.out;
}

struct BadWorldCase {
  const char* name;
  std::string args;
  std::string expected;
};

void PrintTo(const BadWorldCase& c, std::ostream* os) { *os << "nxtmap " << c.args; }

class HonestWorldBad : public ::testing::TestWithParam<BadWorldCase> {};

TEST_P(HonestWorldBad, IsOneLineAndExitTwo) {
  TempDir tmp(std::string("honest_") + GetParam().name);
  tmp.write("open.yaml", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [3, 0]]}\n");
  tmp.write("cross.yaml", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [3, 3], [3, 0], [0, 3]]}\n");
  tmp.write("surface.yaml", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [3, 0], [3, 3], [0, 3]], surface: velvet}\n");
  std::string args = GetParam().args;
  for (size_t at = args.find("{dir}"); at != std::string::npos; at = args.find("{dir}"))
    args.replace(at, 5, tmp.path());
  expectUsageError(runCli(args), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    Table, HonestWorldBad,
    ::testing::Values(
        BadWorldCase{"openPolygon", "sim {dir}/open.yaml --start 1,1", "open.yaml"},
        BadWorldCase{"selfIntersecting", "sim {dir}/cross.yaml --start 1,1", "cross"},
        BadWorldCase{"unknownSurface", "sim {dir}/surface.yaml --start 1,1", "velvet"},
        BadWorldCase{"startInTheSofa", "sim " + kLiving + " --start 2,3.2", "inside an obstacle"},
        BadWorldCase{"startOutside", "sim " + kLiving + " --start 9,9", "start"},
        BadWorldCase{"bodyDoesNotFit", "sim " + kLiving + " --robot brick --start 0.05,2", "does not fit"},
        BadWorldCase{"startNotMetres", "sim " + kLiving + " --start one,2", "X,Y or X,Y,YAW"},
        BadWorldCase{"unknownRobot", "sim " + kTurned + " --robot tank", "--robot must be one of published, brick"},
        BadWorldCase{"jitterTooLarge", "sim " + kTurned + " --start-jitter 60", "--start-jitter must be 0 .. 45"},
        BadWorldCase{"jitterNegative", "sim " + kTurned + " --start-jitter=-1", "--start-jitter"},
        BadWorldCase{"squareMaybe", "sim " + kTurned + " --square maybe", "--square must be auto, yes or no"},
        BadWorldCase{"calibrateMaybe", "sim " + kTurned + " --calibrate=maybe", "--calibrate must be auto, yes or no"},
        BadWorldCase{"calibrateUnsquared", "experiments worlds/seed-appendix-a --calibrate --square no",
                     "--calibrate measures against the walls"},
        BadWorldCase{"houseCalibrateMaybe", "sim-house " + kHouse + " --calibrate=maybe",
                     "--calibrate must be auto, yes or no"},
        BadWorldCase{"houseCalibrateUnsquared", "sim-house " + kHouse + " --calibrate --square no",
                     "--calibrate measures against the walls"},
        BadWorldCase{"unknownPreset", "sim " + kTurned + " --noise lego", "--noise must be one of ideal"},
        BadWorldCase{"noWorld", "sim --noise nxt", "sim: world is required"},
        BadWorldCase{"experimentsRobot", "experiments worlds/seed-appendix-a --robot tank", "--robot"},
        BadWorldCase{"houseBody", "sim-house " + kLiving + " --robot brick --start 0.05,2", "does not fit"}),
    [](const ::testing::TestParamInfo<BadWorldCase>& i) { return std::string(i.param.name); });

}  // namespace
}  // namespace nxtmap::cli::test
