// The nxtmap console run as a process: bad input -> one "nxtmap: " line on stderr and exit 2;
// good runs print their results and write their files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "CliTestSupport.hpp"
#include "host/report/Plots.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kWorld = "worlds/seed-appendix-a/occupancy-089.map";
const std::string kDir = "worlds/seed-appendix-a";
const std::string kHeader =
    "id,actual_free,found_free,actual_occupied,found_occupied,unknown,wrong_cells,detected_pct,time_units,"
    "sensor_reads,seed_time_units,seed_sensor_count,seed_detected_pct,unsafe_free,phantom_occupied,lost,"
    "detected_pct_aligned,wrong_cells_aligned,heading_off_pct,position_off_pct,squared_deg";

// A scenario directory holding `tsv` as scenarios.tsv plus a copy-free link to the real maps.
std::string scenarioDir(const TempDir& tmp, const std::string& name, const std::string& tsv) {
  tmp.write(name + "/scenarios.tsv", tsv);
  return tmp.path(name);
}

void expectUsageError(const std::string& args, const std::string& mention = "") {
  SCOPED_TRACE("nxtmap " + args);
  const RunOutput r = runCli(args);
  EXPECT_EQ(r.exitCode, 2);
  const std::vector<std::string> errLines = lines(r.err);
  ASSERT_EQ(errLines.size(), 1u) << r.err;
  EXPECT_EQ(errLines[0].rfind("nxtmap: ", 0), 0u) << errLines[0];
  if (!mention.empty()) {
    EXPECT_NE(errLines[0].find(mention), std::string::npos) << errLines[0];
  }
}

TEST(CliBadInput, CommandLine) {
  expectUsageError("", "command");
  expectUsageError("frobnicate", "frobnicate");
  expectUsageError("--bogus", "--bogus");
  expectUsageError("sim");
  expectUsageError("sim " + kWorld, "--start");
  expectUsageError("sim " + kWorld + " --start 1,20 --bogus", "--bogus");
  expectUsageError("sim " + kWorld + " --start 1,20 --range-m abc", "--range-m");
  expectUsageError("sim " + kWorld + " extra --start 1,20", "extra");
  expectUsageError("experiments");
}

TEST(CliBadInput, SimValues) {
  const std::string sim = "sim " + kWorld;
  expectUsageError(sim + " --start 1", "--start");
  expectUsageError(sim + " --start a,b", "--start");
  expectUsageError(sim + " --start 1,2,3", "--start");
  expectUsageError(sim + " --start 1.5,2", "--start");
  expectUsageError(sim + " --start 99,1", "outside");
  expectUsageError(sim + " --start=-1,20", "outside");
  expectUsageError(sim + " --start 0,0", "obstacle");
  expectUsageError(sim + " --start 1,20 --heading X", "--heading");
  expectUsageError(sim + " --start 1,20 --noise loud", "--noise");
  expectUsageError(sim + " --start 1,20 --strategy wander", "--strategy");
  expectUsageError(sim + " --start 1,20 --show sometimes", "--show");
  expectUsageError(sim + " --start 1,20 --range-m -1", "--range-m");
  expectUsageError(sim + " --start 1,20 --range-m 0", "--range-m");
  expectUsageError(sim + " --start 1,20 --seed -3", "--seed");
  expectUsageError(sim + " --start 1,20 --delay-ms -5", "--delay-ms");
}

TEST(CliBadInput, Worlds) {
  TempDir tmp("worlds");
  expectUsageError("sim " + tmp.path("missing.map") + " --start 1,1", "missing.map");
  const std::string bad = tmp.write("bad.map", "type octile\nheight 3\nwidth 3\nmap\n...\n..\n");
  expectUsageError("sim " + bad + " --start 1,1", "bad.map");
  const std::string odd = tmp.write("world.txt", "...\n");
  expectUsageError("sim " + odd + " --start 1,1", "world.txt");
}

TEST(CliBadInput, ScenarioTables) {
  TempDir tmp("tables");
  const std::string maps = sourcePath(kDir) + "/";
  const std::string head =
      "# id\tmap\tstart_col\tstart_row\tseed_x_m\tseed_z_m\toccupied_cells\tseed_unknowns\t"
      "seed_time_units\tseed_sensor_count\tseed_detected_pct\n";
  const std::string good = "occ089\t" + maps + "occupancy-089.map\t1\t20\t-0.95\t0.95\t89\t14\t294\t1189\t100\n";
  expectUsageError("experiments " + tmp.path("nowhere"), "nowhere");
  tmp.write("empty/readme", "");
  expectUsageError("experiments " + tmp.path("empty"), "scenarios.tsv");
  expectUsageError("experiments " + scenarioDir(tmp, "short", head + good + "occ095\tx.map\t1\n"), "line 3");
  expectUsageError(
      "experiments " +
          scenarioDir(tmp, "nan",
                      head + "occ089\t" + maps + "occupancy-089.map\tone\t20\t-0.95\t0.95\t89\t14\t294\t1189\t100\n"),
      "line 2");
  expectUsageError(
      "experiments " + scenarioDir(tmp, "nomap", head + good + "occ1\tmissing.map\t1\t20\t0\t0\t1\t1\t1\t1\t1\n"),
      "line 3");
  expectUsageError(
      "experiments " +
          scenarioDir(tmp, "wall", head + "occ1\t" + maps + "occupancy-089.map\t0\t0\t0\t0\t1\t1\t1\t1\t1\n"),
      "line 2");
  expectUsageError("experiments " + scenarioDir(tmp, "none", head), "no scenarios");
  expectUsageError("experiments " + kDir + " --seeds 0", "--seeds");
  expectUsageError("experiments " + kDir + " --strategy wander", "--strategy");
  expectUsageError("experiments " + kDir + " --noise loud", "--noise");
  expectUsageError("experiments " + kDir + " --csv " + tmp.path("no/such/dir/out.csv"), "out.csv");
}

TEST(CliHelp, HelpExitsZero) {
  const RunOutput r = runCli("--help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("sim"), std::string::npos);
  EXPECT_NE(r.out.find("experiments"), std::string::npos);
  const RunOutput s = runCli("sim --help");
  EXPECT_EQ(s.exitCode, 0);
  EXPECT_NE(s.out.find("--start"), std::string::npos);
}

TEST(CliSim, FinalRunPrintsMapAndCounters) {
  const RunOutput r = runCli("sim " + kWorld + " --start 1,20 --show final");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* key : {"time units", "sensor requests", "raw samples", "cells moved", "turns", "detected",
                          "wrong cells", "unknown cells", "+----------------------+"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
  }
  EXPECT_EQ(r.out.find("\x1b["), std::string::npos) << "no colour when not on a terminal";
}

TEST(CliSim, NoDisplayAndPng) {
  TempDir tmp("png");
  const std::string png = tmp.path("map.png");
  const RunOutput r = runCli("sim " + kWorld + " --start 1,20 --show none --strategy frontier --png " + png);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find("+---"), std::string::npos);
  EXPECT_NE(r.out.find("sensor requests"), std::string::npos);
  const std::string data = readFile(png);
  ASSERT_GT(data.size(), 8u);
  EXPECT_EQ(data.substr(1, 3), "PNG");
}

TEST(CliSim, LiveRunRedraws) {
  const RunOutput r = runCli("sim " + kWorld + " --start 1,20 --show live --delay-ms 0");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\x1b[H"), std::string::npos);
  EXPECT_NE(r.out.find("propagation |"), std::string::npos);
  EXPECT_NE(r.out.find("time units"), std::string::npos);
}

TEST(CliExperiments, CsvAndMarkdown) {
  TempDir tmp("exp");
  const std::string csv = tmp.path("results.csv"), md = tmp.path("results.md");
  const RunOutput r = runCli("experiments " + kDir + " --csv " + csv + " --markdown " + md);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("occ089"), std::string::npos);
  EXPECT_NE(r.out.find("median"), std::string::npos);
  const std::vector<std::string> rows = lines(readFile(csv));
  ASSERT_EQ(rows.size(), 19u);
  EXPECT_EQ(rows[0], kHeader);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(std::count(rows[i].begin(), rows[i].end(), ','), 20) << rows[i];
    EXPECT_EQ(rows[i].back(), ',') << "the published robot does not sweep: no squared_deg: " << rows[i];
  }
  EXPECT_EQ(r.out.find("squared to the walls"), std::string::npos) << r.out;
  EXPECT_EQ(rows[1].rfind("occ089,", 0), 0u);
  const std::string markdown = readFile(md);
  EXPECT_NE(markdown.find("| occ089 |"), std::string::npos);
  EXPECT_NE(markdown.find("**median**"), std::string::npos);
  EXPECT_NE(markdown.find("**350.5**"), std::string::npos);
  EXPECT_NE(markdown.find("**1143.5**"), std::string::npos);
}

TEST(CliExperiments, BothStrategiesWriteOneCsvEach) {
  TempDir tmp("both");
  const RunOutput r = runCli("experiments " + kDir + " --strategy both --csv " + tmp.path("r.csv"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"r-propagation.csv", "r-frontier.csv"}) {
    const std::vector<std::string> rows = lines(readFile(tmp.path(name)));
    ASSERT_EQ(rows.size(), 19u) << name;
    EXPECT_EQ(rows[0], kHeader);
  }
  EXPECT_NE(r.out.find("strategy propagation"), std::string::npos);
  EXPECT_NE(r.out.find("strategy frontier"), std::string::npos);
}

TEST(CliExperiments, Plots) {
  if (report::findGnuplot().empty()) GTEST_SKIP() << "gnuplot is not installed";
  TempDir tmp("plots");
  const std::string dir = tmp.path("plots");
  const RunOutput r = runCli("experiments " + kDir + " --plots " + dir);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  for (const char* name : {"fig5_3.png", "fig5_4.png", "fig5_6.png"}) {
    const std::string data = readFile(dir + "/" + name);
    ASSERT_GT(data.size(), 1000u) << name;
    EXPECT_EQ(data.substr(1, 3), "PNG") << name;
  }
}

}  // namespace
}  // namespace nxtmap::cli::test
