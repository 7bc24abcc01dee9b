// Unit tests of the report library's experiment table: numbers and medians, the CSV columns, how square the runs
// started, and the scenario table's malformed lines.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "CliTestSupport.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::report {
namespace {

TEST(ExperimentTable, NumbersAndMedians) {
  EXPECT_EQ(formatNumber(294), "294");
  EXPECT_EQ(formatNumber(294.5), "294.5");
  EXPECT_EQ(formatNumber(97.8666), "97.87");
  EXPECT_EQ(formatNumber(-0.0001), "0");
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(median({4, 1, 2, 3}), 2.5);
  EXPECT_DOUBLE_EQ(median({}), 0);
}

TEST(ExperimentTable, PublishedMediansOfTheTable) {
  const ScenarioLoad load = loadScenarios(cli::test::sourcePath("worlds/seed-appendix-a/scenarios.tsv"));
  ASSERT_TRUE(load.error.empty()) << load.error;
  ASSERT_EQ(load.scenarios.size(), 18u);
  ExperimentTable t;
  for (const Scenario& s : load.scenarios) {
    ExperimentRow row;
    row.scenario = s;
    t.rows.push_back(row);
  }
  EXPECT_DOUBLE_EQ(t.publishedMedianTimeUnits(), kPublishedMedianTimeUnits);
  EXPECT_DOUBLE_EQ(t.publishedMedianSensorReads(), kPublishedMedianSensorReads);
  EXPECT_EQ(load.scenarios[9].id, "start-0.95+0.95");
  EXPECT_TRUE(load.scenarios[9].isStartRun());
  EXPECT_TRUE(load.scenarios[0].isOccupancyRun());
}

TEST(ExperimentTable, CsvColumnsAndMeans) {
  ExperimentTable t;
  ExperimentRow row;
  row.scenario.id = "occ1";
  row.scenario.seedTimeUnits = 294;
  row.scenario.seedSensorCount = 1189;
  row.scenario.seedDetectedPct = 100;
  RunResult a, b;
  a.timeUnits = 100;
  b.timeUnits = 101;
  a.detectedPct = 100;
  b.detectedPct = 90;
  a.wrongCells = 0;
  b.wrongCells = 3;
  a.unsafeFree = 0;
  b.unsafeFree = 2;
  a.phantomOccupied = 0;
  b.phantomOccupied = 1;
  a.lost = 0;
  b.lost = 1;
  a.detectedPctAligned = 100;
  b.detectedPctAligned = 97;
  a.wrongCellsAligned = 0;
  b.wrongCellsAligned = 1;
  a.headingOffPct = 2;
  b.headingOffPct = 7;
  a.positionOffPct = 10;
  b.positionOffPct = 40.5;
  b.squared = true;  // a's sweep found no wall: its squared_deg is empty and the mean is b's alone
  b.squaredDeg = -1.5;
  row.perSeed = {a, b};
  row.summarize();
  EXPECT_DOUBLE_EQ(row.mean.timeUnits, 100.5);
  EXPECT_DOUBLE_EQ(row.minDetectedPct, 90);
  EXPECT_DOUBLE_EQ(row.maxWrongCells, 3);
  t.rows.push_back(row);
  std::ostringstream csv;
  t.writeCsv(csv);
  const std::vector<std::string> rows = cli::test::lines(csv.str());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], ExperimentTable::csvHeader());
  EXPECT_EQ(rows[1], "occ1,0,0,0,0,0,1.5,95,100.5,0,294,1189,100,1,0.5,0.5,98.5,0.5,4.5,25.25,-1.5");
  // The older columns keep their places; the safety columns follow them, then the localisation's and the start's.
  EXPECT_EQ(
      std::string(ExperimentTable::csvHeader())
          .rfind("id,actual_free,found_free,actual_occupied,found_occupied,unknown,wrong_cells,detected_pct,time_units,"
                 "sensor_reads,seed_time_units,seed_sensor_count,seed_detected_pct,",
                 0),
      0u);
  const std::string tail = std::string(kSafetyColumns) + "," + kPoseColumns + "," + kStartColumns;
  EXPECT_EQ(rows[0].substr(rows[0].size() - tail.size()), tail);

  t.strategy = "propagation";
  t.noise = "typical";
  std::ostringstream seedCsv;
  t.writeSeedCsv(seedCsv);
  const std::vector<std::string> seedRows = cli::test::lines(seedCsv.str());
  ASSERT_EQ(seedRows.size(), 3u);
  EXPECT_EQ(seedRows[0],
            "id,strategy,noise,seed,actual_free,found_free,actual_occupied,found_occupied,unknown,unknown_observable,"
            "wrong_cells,detected_pct,performance_pct,time_units,sensor_reads,complete,unsafe_free,phantom_occupied,"
            "lost,detected_pct_aligned,wrong_cells_aligned,heading_off_pct,position_off_pct,squared_deg");
  EXPECT_EQ(seedRows[1], "occ1,propagation,typical,1,0,0,0,0,0,0,0,100,0,100,0,1,0,0,0,100,0,2,10,");
  EXPECT_EQ(seedRows[2], "occ1,propagation,typical,2,0,0,0,0,0,0,3,90,0,101,0,1,2,1,1,97,1,7,40.5,-1.5");
}

// How square the runs started, over those whose sweep found the walls: (squared?, degrees) per run.
struct SquaringCase {
  const char* name;
  std::vector<std::pair<bool, double>> runs;
  int squared;
  double meanDeg, rmsDeg;
  const char* line;  // what the console prints after the table ("" for nothing)
};

void PrintTo(const SquaringCase& c, std::ostream* os) { *os << c.name; }

class ExperimentSquaring : public ::testing::TestWithParam<SquaringCase> {};

TEST_P(ExperimentSquaring, CountsMeanAndRmsOverTheRunsThatFoundTheWalls) {
  const SquaringCase& c = GetParam();
  ExperimentTable t;
  ExperimentRow row;
  row.scenario.id = "occ1";
  for (const auto& [found, deg] : c.runs) {
    RunResult r;
    r.squared = found;
    r.squaredDeg = deg;
    row.perSeed.push_back(r);
  }
  row.summarize();
  t.rows = {row, row};  // two scenarios: every run counts once
  const ExperimentTable::Squaring s = t.squaring();
  EXPECT_EQ(s.runs, 2 * static_cast<int>(c.runs.size()));
  EXPECT_EQ(s.squared, 2 * c.squared);
  EXPECT_NEAR(s.meanDeg, c.meanDeg, 1e-9);
  EXPECT_NEAR(s.rmsDeg, c.rmsDeg, 1e-9);
  EXPECT_EQ(row.mean.squared, c.squared > 0);
  if (c.squared > 0) {
    EXPECT_NEAR(row.mean.squaredDeg, c.meanDeg, 1e-9);
  }
  std::ostringstream console;
  t.writeConsole(console);
  const std::string out = console.str();
  if (*c.line == '\0') {
    EXPECT_EQ(out.find("squared to the walls"), std::string::npos) << out;
  } else {
    EXPECT_NE(out.find(c.line), std::string::npos) << out;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, ExperimentSquaring,
    ::testing::Values(
        SquaringCase{"noSweep", {{false, 0}, {false, 0}}, 0, 0, 0, ""},
        SquaringCase{"allSquared",
                     {{true, 3}, {true, -1}},
                     2,
                     1,
                     std::sqrt(5.0),
                     "squared to the walls in 4 of 4 runs: left 1 deg clockwise of them on average, 2.24 deg rms"},
        SquaringCase{
            "oneFoundNoWall",
            {{true, -2}, {false, 9}, {true, -0.5}},
            2,
            -1.25,
            std::sqrt(2.125),
            "squared to the walls in 4 of 6 runs: left 1.25 deg anticlockwise of them on average, 1.46 deg rms"}),
    [](const ::testing::TestParamInfo<SquaringCase>& i) { return std::string(i.param.name); });

TEST(ExperimentTable, MalformedLinesAreNamed) {
  cli::test::TempDir tmp("tsv");
  const std::string path = tmp.write("s.tsv", "# header\n\nocc1\tm.map\t1\t2\t0\t0\t1\t1\t1\t1\t1\nocc2\tm.map\t1\n");
  const ScenarioLoad load = loadScenarios(path);
  EXPECT_TRUE(load.scenarios.empty());
  EXPECT_NE(load.error.find("line 4"), std::string::npos) << load.error;
  const ScenarioLoad dup =
      loadScenarios(tmp.write("d.tsv", "a\tm.map\t1\t2\t0\t0\t1\t1\t1\t1\t1\na\tm.map\t1\t2\t0\t0\t1\t1\t1\t1\t1\n"));
  EXPECT_NE(dup.error.find("duplicate"), std::string::npos) << dup.error;
  const ScenarioLoad ok = loadScenarios(tmp.write("ok.tsv", "a\tm.map\t1\t2\t0\t0\t1\t1\t1.5\t1\t1\r\n"));
  ASSERT_TRUE(ok.error.empty()) << ok.error;
  EXPECT_EQ(ok.scenarios[0].mapPath, tmp.path("m.map"));
  EXPECT_DOUBLE_EQ(ok.scenarios[0].seedTimeUnits, 1.5);
}

}  // namespace
}  // namespace nxtmap::report
