// `nxtmap sim-house --trace FILE.csv`: every action of a house run (rooms, travels, crossings) with the believed
// and the true pose on the world's raster, as a process writes them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"
#include "TraceCliSupport.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kHeader =
    "step,order,action,value,sensor,reading_cm,reading,true_col,true_row,true_heading_deg,believed_col,believed_row,"
    "believed_heading,est_x_mm,est_y_mm,est_theta_mrad,lost";
const std::string kHouse = "sim-house worlds/houses/three-rooms.map --start 8,8 ";

TEST(SimHouseTrace, AnIdealHouseRunIsTracedActionByActionOnItsCells) {
  TempDir tmp("housetrace");
  const std::string csv = tmp.path("run.csv");
  const RunOutput r = runCli(kHouse + "--trace " + csv);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<std::string> rows = lines(readFile(csv));
  ASSERT_GT(rows.size(), 500u);
  EXPECT_EQ(rows[0], kHeader);
  std::ostringstream said;
  said << "wrote " << csv << ": " << rows.size() - 1
       << " actions; the believed cell was the robot's after every action";
  EXPECT_NE(r.out.find(said.str()), std::string::npos) << r.out;
  std::set<std::string> orders;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = csvFields(rows[i]);
    ASSERT_EQ(f.size(), 17u) << rows[i];
    EXPECT_EQ(std::strtol(f[0].c_str(), nullptr, 10), static_cast<long>(i)) << "one row per action, from 1";
    EXPECT_EQ(f[2] == "read", !f[4].empty()) << "a sensor for readings only: " << rows[i];
    orders.insert(f[1]);
    if (f[10].empty()) continue;  // nothing believed yet
    // The published robot without noise: on its believed cell's centre, square to its believed heading (its
    // quarter turns are whole mrad, 1571: a tenth of a degree off now and then, and a few mm after long drives).
    EXPECT_NEAR(std::strtod(f[7].c_str(), nullptr), std::strtod(f[10].c_str(), nullptr), 0.05) << rows[i];
    EXPECT_NEAR(std::strtod(f[8].c_str(), nullptr), std::strtod(f[11].c_str(), nullptr), 0.05) << rows[i];
    const double heading = std::strtod(f[9].c_str(), nullptr);
    const std::string nesw = "NESW";
    const double quarter = 90.0 * static_cast<double>(nesw.find(f[12]));
    EXPECT_NEAR(std::remainder(heading - quarter, 360.0), 0.0, 0.2) << rows[i];  // 1571 mrad a quarter
    EXPECT_EQ(f[16], "0") << rows[i];
  }
  // Three rooms: mapped, travelled between and crossed into.
  for (const char* o : {"room", "travel", "cross"}) EXPECT_EQ(orders.count(o), 1u) << o;
}

TEST(SimHouseTrace, LostMeansTheTruthInAnotherCellThanTheBelief) {
  TempDir tmp("housetrace");
  const std::string csv = tmp.path("run.csv");
  const RunOutput r =
      runCli(kHouse + "--robot brick --noise nxt --start-jitter 5 --seed 3 --strategy propagation --trace " + csv);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<std::string> rows = lines(readFile(csv));
  ASSERT_GT(rows.size(), 500u);
  long firstLost = 0, lostRows = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string> f = csvFields(rows[i]);
    ASSERT_EQ(f.size(), 17u) << rows[i];
    if (f[10].empty()) continue;
    const double col = std::strtod(f[7].c_str(), nullptr), row = std::strtod(f[8].c_str(), nullptr);
    const bool onAFace = std::fabs(std::fabs(std::remainder(col, 1.0)) - 0.5) < 0.01 ||
                         std::fabs(std::fabs(std::remainder(row, 1.0)) - 0.5) < 0.01;
    const bool other = std::floor(col + 0.5) != std::strtod(f[10].c_str(), nullptr) ||
                       std::floor(row + 0.5) != std::strtod(f[11].c_str(), nullptr);
    if (!onAFace) {
      EXPECT_EQ(f[16] == "1", other) << rows[i];
    }
    if (f[16] == "1") {
      ++lostRows;
      if (firstLost == 0) firstLost = std::strtol(f[0].c_str(), nullptr, 10);
    }
  }
  EXPECT_NE(r.out.find(lostSummary(firstLost, lostRows)), std::string::npos) << r.out;
}

TEST(SimHouseTrace, ABadTraceFileIsRefusedBeforeTheRun) { expectBadTracesRefused(kHouse, "agreement"); }

}  // namespace
}  // namespace nxtmap::cli::test
