// `nxtmap path` and `nxtmap paths` from the outside: output, drawing, labels, and bad input (exit 2, one line).
#include <gtest/gtest.h>

#include <string>

#include "host/mapio/MapFiles.hpp"
#include "tests/cli/CliTestSupport.hpp"

namespace nxtmap::plan {
namespace {

using cli::test::lines;
using cli::test::readFile;
using cli::test::runCli;
using cli::test::RunOutput;
using cli::test::shellQuote;
using cli::test::TempDir;

const std::string kRoom = "worlds/seed-appendix-a/occupancy-120.map";

void expectUsageError(const std::string& args, const std::string& mention) {
  const RunOutput r = runCli(args);
  EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.out << r.err;
  const auto errLines = lines(r.err);
  ASSERT_EQ(errLines.size(), 1u) << args << "\n" << r.err;
  EXPECT_EQ(errLines[0].rfind("nxtmap: ", 0), 0u) << errLines[0];
  EXPECT_NE(errLines[0].find(mention), std::string::npos) << args << "\n" << errLines[0];
}

TEST(PathCli, DrawsThePathAndPrintsLengthAndNodes) {
  for (const char* algo : {"astar", "jps", "jps+", "seed", "dijkstra"}) {
    const RunOutput r = runCli("path " + kRoom + " --from 1,20 --to 20,1 --algo " + algo);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("S"), std::string::npos);
    EXPECT_NE(r.out.find("algorithm        " + std::string(algo)), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("nodes expanded"), std::string::npos);
    const auto out = lines(r.out);
    ASSERT_GT(out.size(), 22u);
    EXPECT_EQ(out[1].back(), '#');
    EXPECT_EQ(out[1][20], 'G');  // the goal cell, row 1 col 20
    EXPECT_EQ(out[20][1], 'S');
  }
  // The optimal planners agree on the length.
  const RunOutput a = runCli("path " + kRoom + " --from 1,20 --to 20,1 --draw never");
  const RunOutput j = runCli("path " + kRoom + " --from 1,20 --to 20,1 --draw never --algo jps");
  const auto lengthLine = [](const std::string& text) { return text.substr(text.find("length"), 40); };
  EXPECT_EQ(lengthLine(a.out), lengthLine(j.out));
  EXPECT_EQ(a.out.find('#'), std::string::npos);  // --draw never
}

TEST(PathCli, NearALabelFromTheCommandLineOrTheMapFile) {
  const RunOutput r = runCli("path " + kRoom + " --from 1,20 --to near:table --label table=11,9,2,2 --draw never");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("(next to table)"), std::string::npos) << r.out;

  // A saved map carrying labels (unknown cells beyond what was explored).
  TempDir tmp("pathcli");
  mapio::OccupancyMap m(6, 4, mapio::Occupancy::Free);
  m.set(3, 1, mapio::Occupancy::Occupied);
  m.set(5, 3, mapio::Occupancy::Unknown);
  ASSERT_TRUE(m.setLabel("chair", mapio::CellBlock{3, 1, 1, 1}));
  std::string error;
  ASSERT_TRUE(mapio::saveRosMap(m, tmp.path("room.yaml"), error)) << error;
  const RunOutput s = runCli("path " + shellQuote(tmp.path("room.yaml")) + " --from 0,0 --to near:chair");
  ASSERT_EQ(s.exitCode, 0) << s.err;
  EXPECT_NE(s.out.find("to               2,0 (next to chair)"), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("L"), std::string::npos);
  expectUsageError("path " + shellQuote(tmp.path("room.yaml")) + " --from 0,0 --to 5,3", "unknown cell");
  EXPECT_EQ(runCli("path " + shellQuote(tmp.path("room.yaml")) + " --from 0,0 --to 5,3 --through-unknown").exitCode, 0);
  expectUsageError("path " + shellQuote(tmp.path("room.yaml")) + " --from 0,0 --to near:sofa", "labels: chair");
}

TEST(PathCli, BadInputIsOneLineAndExitTwo) {
  TempDir tmp("pathbad");
  const std::string p = "path " + kRoom;
  expectUsageError("path", "map");
  expectUsageError(p + " --to 3,3", "--from");
  expectUsageError(p + " --from 1,20", "--to");
  expectUsageError(p + " --from 1,20 --to 3", "--to");
  expectUsageError(p + " --from 30,2 --to 3,3", "outside the 22x22 map");
  expectUsageError(p + " --from 1,20 --to=-1,3", "outside");
  expectUsageError(p + " --from 0,0 --to 3,3", "--from 0,0 is an occupied cell");
  expectUsageError(p + " --from 1,20 --to 0,5", "--to 0,5 is an occupied cell");
  expectUsageError(p + " --from 1,20 --to near:chair", "unknown label 'chair'");
  expectUsageError(p + " --from 1,20 --to 3,3 --algo bfs", "--algo");
  expectUsageError(p + " --from 1,20 --to 3,3 --draw maybe", "--draw");
  expectUsageError(p + " --from 1,20 --to 3,3 --clearance -1", "--clearance");
  expectUsageError(p + " --from 1,20 --to 3,3 --clearance 1", "--clearance 1");
  expectUsageError(p + " --from 1,20 --to 3,3 --label x=1", "--label");
  expectUsageError(p + " --from 1,20 --to 3,3 --label x=99,1", "outside");
  const std::string walled = tmp.write("walled.map", "type octile\nheight 3\nwidth 5\nmap\n..@..\n..@..\n..@..\n");
  expectUsageError("path " + walled + " --from 0,0 --to 4,2", "no path from 0,0 to 4,2");
  expectUsageError("path " + walled + " --from 0,0 --to near:door --label door=4,1", "no usable cell next to it");
  const std::string bad = tmp.write("bad.map", "type octile\nheight 3\nwidth 3\nmap\n...\n..\n");
  expectUsageError("path " + bad + " --from 0,0 --to 1,1", "bad.map");
  expectUsageError("path " + tmp.path("none.yaml") + " --from 0,0 --to 1,1", "none.yaml");
}

TEST(PathsCli, RunsAScenarioFileAndChecksTheOptima) {
  TempDir tmp("pathscli");
  const std::string map = "worlds/movingai/dao/arena2.map";
  // A few lines of the published file.
  const std::string all = readFile(std::string(NXTMAP_SOURCE_DIR) + "/" + map + ".scen");
  const auto ls = lines(all);
  std::string few = ls[0] + "\n";
  for (size_t i = 1; i < ls.size(); i += 60) few += ls[i] + "\n";
  const std::string scen = tmp.write("few.scen", few);
  for (const char* algo : {"astar", "jps", "jps+"}) {
    const RunOutput r = runCli("paths " + map + " --scen " + shellQuote(scen) + " --algo " + algo + " --csv " +
                               shellQuote(tmp.path("out.csv")));
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("matched          16 of 16 published optima"), std::string::npos) << r.out;
    const auto csv = lines(readFile(tmp.path("out.csv")));
    ASSERT_EQ(csv.size(), 17u);
    EXPECT_EQ(csv[0].rfind("index,bucket,", 0), 0u);
  }
  // A wrong optimum is reported and makes the exit code 1 (a failed check, not bad input).
  std::string wrong = ls[0] + "\n" + ls[100] + "\n";
  wrong.replace(wrong.rfind('\t') + 1, std::string::npos, "1.00000000\n");
  const RunOutput w = runCli("paths " + map + " --scen " + shellQuote(tmp.write("wrong.scen", wrong)));
  EXPECT_EQ(w.exitCode, 1) << w.out << w.err;
  EXPECT_NE(w.out.find("mismatch"), std::string::npos) << w.out;
}

TEST(PathsCli, BadInputIsOneLineAndExitTwo) {
  TempDir tmp("pathsbad");
  const std::string map = "worlds/movingai/dao/arena2.map";
  expectUsageError("paths " + map, "--scen");
  expectUsageError("paths " + map + " --scen " + tmp.path("none.scen"), "none.scen");
  expectUsageError("paths " + map + " --scen " + tmp.write("v.scen", "version 7\n"), "version 1");
  expectUsageError("paths " + map + " --scen " + tmp.write("f.scen", "version 1\n0\tarena2.map\t281\t209\t1\t2\n"),
                   "expected 9 fields");
  expectUsageError(
      "paths " + map + " --scen " + tmp.write("s.scen", "version 1\n0\tarena2.map\t512\t512\t1\t2\t3\t4\t5\n"),
      "is for a 512x512 map");
  expectUsageError(
      "paths " + map + " --scen " + tmp.write("o.scen", "version 1\n0\tarena2.map\t281\t209\t1\t2\t300\t4\t5\n"),
      "outside the map");
  expectUsageError("paths " + map + " --scen " + tmp.write("e.scen", "version 1\n"), "no problems");
  expectUsageError("paths " + tmp.write("m.map", "type octile\nheight 1\n") + " --scen " + tmp.path("e.scen"), "m.map");
  expectUsageError("paths " + map + " --scen " + tmp.path("e.scen") + " --algo bfs", "--algo");
}

}  // namespace
}  // namespace nxtmap::plan
