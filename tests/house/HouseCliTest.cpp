#include <gtest/gtest.h>

#include <filesystem>

#include "tests/cli/CliTestSupport.hpp"

namespace nxtmap::cli::test {
namespace {

bool oneLineError(const RunOutput& r, const std::string& part) {
  return r.exitCode == 2 && r.err.rfind("nxtmap: ", 0) == 0 && r.err.find('\n') == r.err.size() - 1 &&
         r.err.find(part) != std::string::npos;
}

TEST(HouseCli, SimHouseSavesAHouseThatExportsAndRoutes) {
  TempDir t("house_cli");
  const std::string dir = t.path("house");
  const RunOutput run = runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(dir));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("rooms            3"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("gateways         3"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("agreement        100 %"), std::string::npos) << run.out;
  for (const char* f : {"house.yaml", "room0.yaml", "room0.pgm", "room1.yaml", "room2.pgm"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  }

  const RunOutput ex = runCli("export " + shellQuote(dir) + " --png " + shellQuote(t.path("h.png")) + " --svg " +
                              shellQuote(t.path("h.svg")) + " --ros " + shellQuote(t.path("ros")));
  ASSERT_EQ(ex.exitCode, 0) << ex.err;
  EXPECT_EQ(readFile(t.path("h.png")).substr(1, 3), "PNG");
  EXPECT_NE(readFile(t.path("h.svg")).find("class=\"gateway\""), std::string::npos);
  EXPECT_NE(readFile(t.path("ros/merged.yaml")).find("image: merged.pgm"), std::string::npos);
  // The merged ROS map covers the whole house (40 x 32 world cells, all walls seen) and holds free
  // (254) and occupied (0) pixels.
  const std::string pgm = readFile(t.path("ros/merged.pgm"));
  EXPECT_EQ(pgm.rfind("P5", 0), 0u);
  EXPECT_NE(pgm.find("\n40 32\n"), std::string::npos);
  EXPECT_NE(pgm.find(static_cast<char>(254)), std::string::npos);
  EXPECT_NE(pgm.find(static_cast<char>(0), 20), std::string::npos);

  const RunOutput route = runCli("path --house " + shellQuote(dir) + " --from room0:3,3 --to room2:25,5");
  ASSERT_EQ(route.exitCode, 0) << route.err;
  EXPECT_NE(route.out.find("rooms            room0 -> room2"), std::string::npos) << route.out;
}

TEST(HouseCli, HouseExpoPlanAndLabels) {
  TempDir t("house_cli_expo");
  const std::string dir = t.path("h");
  const RunOutput run =
      runCli("sim-house worlds/houseexpo/1f99717550c31ae321ca2313edceedcc.json --save " + shellQuote(dir));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.out.find("rooms            2 (plan: 2 rooms"), std::string::npos) << run.out;
  const RunOutput near = runCli("path --house " + shellQuote(dir) + " --from room0:15,20 --to near:living_room");
  EXPECT_EQ(near.exitCode, 0) << near.err << near.out;
  EXPECT_NE(near.out.find("room0 -> room1"), std::string::npos) << near.out;
}

TEST(HouseCli, BadInputIsOneClearMessage) {
  TempDir t("house_cli_bad");
  EXPECT_TRUE(oneLineError(runCli("sim-house worlds/houses/missing.map --start 1,1"), "missing.map"));
  EXPECT_TRUE(oneLineError(runCli("sim-house worlds/houses/three-rooms.map"), "--start"));
  EXPECT_TRUE(oneLineError(runCli("sim-house worlds/houses/three-rooms.map --start 0,0"), "0,0"));
  EXPECT_TRUE(oneLineError(runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --noise loud"), "noise"));
  const std::string broken = t.write("broken.json", "{\"verts\": [[0, 0], [1, 0]]}");
  EXPECT_TRUE(oneLineError(runCli("sim-house " + shellQuote(broken)), "at least 3"));
  // A directory that is not a house is never overwritten.
  t.write("mine/notes.txt", "keep");
  EXPECT_TRUE(oneLineError(runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " +
                                  shellQuote(t.path("mine"))),
                           "not overwritten"));
  EXPECT_EQ(readFile(t.path("mine/notes.txt")), "keep");
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("nowhere")) + " --png x.png"), "no house file"));
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("mine"))), "at least one of"));
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("nowhere")) + " --from a:1,1 --to b:1,1"),
                           "no house file"));
  // A house with a broken file: one message, nothing half-loaded.
  ASSERT_EQ(runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(t.path("h"))).exitCode, 0);
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0:3,3 --to room9:1,1"),
                           "no room 'room9'"));
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0:0,0 --to room1:3,3"),
                           "not a free cell"));
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0 --to room1:3,3"),
                           "ROOM:COL,ROW"));
  std::filesystem::remove(t.path("h/room1.pgm"));
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("h")) + " --png " + shellQuote(t.path("x.png"))),
                           "room 'room1'"));
  EXPECT_FALSE(std::filesystem::exists(t.path("x.png")));
}

}  // namespace
}  // namespace nxtmap::cli::test
