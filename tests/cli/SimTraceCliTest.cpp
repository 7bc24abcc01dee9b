// `nxtmap sim --trace FILE.csv`: the believed and the true pose after every action, as a process writes them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"
#include "TraceCliSupport.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kHeader =
    "step,action,value,sensor,reading_cm,reading,true_x_mm,true_y_mm,true_theta_mrad,cell_x,cell_y,heading,est_x_mm,"
    "est_y_mm,est_theta_mrad,"
    "err_x_mm,err_y_mm,err_theta_mrad,lost,sd_x_mm,sd_y_mm,sd_theta_mrad";

long num(const std::string& f) { return std::strtol(f.c_str(), nullptr, 10); }

TEST(SimTrace, AnIdealRunNeverLeavesItsCellAndTracesEveryAction) {
  TempDir tmp("trace");
  const std::string csv = tmp.path("run.csv");
  const RunOutput r = runCli("sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --show none --trace " + csv);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("the believed cell was the robot's after every action"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("outside the tracker's 3 sigma after 0 of "), std::string::npos) << r.out;
  const std::vector<std::string> rows = lines(readFile(csv));
  ASSERT_GT(rows.size(), 100u);
  EXPECT_EQ(rows[0], kHeader);
  // The published robot, no noise: on its cell's centre (10 cm cells; the simulated wheels' arithmetic may leave
  // it a few tenths of a mm off after each move, 2 mm at most over a run), square, after every action.
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = csvFields(rows[i]);
    ASSERT_EQ(f.size(), 22u) << rows[i];
    EXPECT_EQ(num(f[0]), static_cast<long>(i)) << "one row per action, numbered from 1";
    EXPECT_EQ(f[1] == "read", !f[3].empty()) << "a sensor for readings only: " << rows[i];
    EXPECT_NEAR(num(f[6]), 100 * num(f[9]), 3) << rows[i];
    EXPECT_NEAR(num(f[7]), 100 * num(f[10]), 3) << rows[i];
    EXPECT_EQ(num(f[8]), 0) << rows[i];
    EXPECT_EQ(f[18], "0") << rows[i];
  }
  const std::vector<std::string> first = csvFields(rows[1]);
  EXPECT_EQ(first[1], "read") << "the first action reads the front sensor where it was set down";
  EXPECT_EQ(first[3], "F");
  // Occupancy-089 from 1,20 facing north: the far wall 1.95 m ahead, beyond the published robot's 1 m.
  EXPECT_EQ(first[4], "195") << rows[1];
  EXPECT_EQ(first[5], "too-far") << rows[1];
}

TEST(SimTrace, TheErrorIsTheTruthLessTheBeliefAndLostMeansAnotherCell) {
  TempDir tmp("trace");
  const std::string csv = tmp.path("run.csv");
  const RunOutput r = runCli(
      "sim worlds/seed-appendix-a/start-positions.map --start 11,11 --robot brick --noise nxt "
      "--start-jitter 10 --seed 2 --show none --trace " +
      csv);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<std::string> rows = lines(readFile(csv));
  ASSERT_GT(rows.size(), 100u);
  long firstLost = 0, lostRows = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = csvFields(rows[i]);
    ASSERT_EQ(f.size(), 22u) << rows[i];
    // 20 cm cells; each column is rounded to whole mm or mrad on its own, so the sum may be 1 off.
    EXPECT_NEAR(num(f[15]), num(f[6]) - (200 * num(f[9]) + num(f[12])), 1) << rows[i];
    EXPECT_NEAR(num(f[16]), num(f[7]) - (200 * num(f[10]) + num(f[13])), 1) << rows[i];
    EXPECT_NEAR(num(f[17]), num(f[8]) - num(f[14]), 1) << rows[i];
    const double cellX = std::floor(num(f[6]) / 200.0 + 0.5), cellY = std::floor(num(f[7]) / 200.0 + 0.5);
    const bool onACellFace = std::fabs(std::fabs(std::fmod(num(f[6]), 200.0)) - 100) <= 1 ||
                             std::fabs(std::fabs(std::fmod(num(f[7]), 200.0)) - 100) <= 1;
    if (!onACellFace) {
      EXPECT_EQ(f[18] == "1", cellX != num(f[9]) || cellY != num(f[10])) << rows[i];
    }
    if (f[18] == "1") {
      ++lostRows;
      if (firstLost == 0) firstLost = num(f[0]);
    }
  }
  EXPECT_NE(r.out.find(lostSummary(firstLost, lostRows)), std::string::npos) << r.out;
  // The consistency count: the last `mapping` rows (the explorer's), those whose error exceeds 3 of the tracker's
  // sigma and the rounding on x, y or heading; recounted from the rounded columns, so within a few of it.
  long outside = 0, mapping = 0;
  ASSERT_EQ(
      std::sscanf(r.out.substr(r.out.find("3 sigma after ")).c_str(), "3 sigma after %ld of %ld", &outside, &mapping),
      2)
      << r.out;
  ASSERT_GT(mapping, 100);
  ASSERT_LT(mapping, static_cast<long>(rows.size()));
  long recount = 0;
  for (size_t i = rows.size() - static_cast<size_t>(mapping); i < rows.size(); ++i) {
    const std::vector<std::string> f = csvFields(rows[i]);
    bool out = false;
    for (int k = 0; k < 3; ++k) out = out || std::labs(num(f[15 + k])) > 3 * num(f[19 + k]) + 1;
    if (out) ++recount;
  }
  EXPECT_NEAR(outside, recount, mapping / 50) << r.out;
  // The sweep's line gives the heading it left, signed: the first mapping row's heading error, the belief then
  // being square (+ clockwise; 0.1 deg is 1.7 mrad).
  const size_t at = r.out.find("turned square: left ");
  ASSERT_NE(at, std::string::npos) << r.out;
  double deg = 0;
  char way[16] = {};
  ASSERT_EQ(std::sscanf(r.out.c_str() + at, "turned square: left %lf deg %15s of them", &deg, way), 2) << r.out;
  ASSERT_TRUE(std::string(way) == "clockwise" || std::string(way) == "anticlockwise") << way;
  const double signedMrad = (std::string(way) == "clockwise" ? 1 : -1) * deg * 17.4533;
  const std::vector<std::string> first = csvFields(rows[rows.size() - static_cast<size_t>(mapping)]);
  EXPECT_NEAR(num(first[17]), signedMrad, 2.0) << rows[rows.size() - static_cast<size_t>(mapping)];
}

TEST(SimTrace, ABadTraceFileIsRefusedBeforeTheRun) {
  expectBadTracesRefused("sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --show none", "time units");
}

}  // namespace
}  // namespace nxtmap::cli::test
