#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <vector>

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
  EXPECT_NE(run.out.find("best frames      100 %"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("the frames cost 0 points"), std::string::npos) << run.out;
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
  EXPECT_TRUE(
      oneLineError(runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(t.path("mine"))),
                   "not overwritten"));
  EXPECT_EQ(readFile(t.path("mine/notes.txt")), "keep");
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("nowhere")) + " --png x.png"), "no house file"));
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("mine"))), "at least one of"));
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("nowhere")) + " --from a:1,1 --to b:1,1"),
                           "no house file"));
  // A house with a broken file: one message, nothing half-loaded.
  ASSERT_EQ(runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(t.path("h"))).exitCode,
            0);
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0:3,3 --to room9:1,1"),
                           "no room 'room9'"));
  EXPECT_TRUE(oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0:0,0 --to room1:3,3"),
                           "not a free cell"));
  EXPECT_TRUE(
      oneLineError(runCli("path --house " + shellQuote(t.path("h")) + " --from room0 --to room1:3,3"), "ROOM:COL,ROW"));
  std::filesystem::remove(t.path("h/room1.pgm"));
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(t.path("h")) + " --png " + shellQuote(t.path("x.png"))),
                           "room 'room1'"));
  EXPECT_FALSE(std::filesystem::exists(t.path("x.png")));
}

// Two 3 x 3 free rooms written by hand, side by side, joined by a gateway; `edit` changes house.yaml's
// text (from -> to) and room0.yaml's origin may be given. Returns the house directory.
std::string handHouse(const TempDir& t, const std::string& name, const std::string& from, const std::string& to,
                      const std::string& room0Origin = "[0, 0, 0]") {
  const std::string pgm = "P5\n3 3\n255\n" + std::string(9, static_cast<char>(254));
  const auto rosYaml = [](const std::string& image, const std::string& origin) {
    return "image: " + image + "\nresolution: 0.1\norigin: " + origin +
           "\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  };
  std::string house =
      "format: nxtmap-house-1\nresolution: 0.1\nrooms:\n"
      "  - name: room0\n    map: room0.yaml\n    to_house: {x: 0, y: 0, quarter_turns_clockwise: 0}\n"
      "    labels:\n      chair: [1, 1]\n"
      "  - name: room1\n    map: room1.yaml\n    to_house: {x: 3, y: 0, quarter_turns_clockwise: 0}\n    labels: {}\n"
      "gateways:\n  - rooms: [room0, room1]\n    cells_a: [[2, 1]]\n    cells_b: [[0, 1]]\n";
  if (!from.empty()) {
    const size_t at = house.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    house.replace(at, from.size(), to);
  }
  t.write(name + "/room0.pgm", pgm);
  t.write(name + "/room1.pgm", pgm);
  t.write(name + "/room0.yaml", rosYaml("room0.pgm", room0Origin));
  t.write(name + "/room1.yaml", rosYaml("room1.pgm", "[0, 0, 0]"));
  t.write(name + "/house.yaml", house);
  return t.path(name);
}

// Numbers in a saved house beyond its bounds (a far room map origin once wrote outside the heap; rooms
// far apart built a 4 GB merged map; a huge to_house, label or gateway cell wrapped silently): path
// --house, export and connect --house each give one line naming the field, exit 2, and write nothing.
TEST(HouseCli, HouseNumbersBeyondTheirBoundsAreOneClearMessage) {
  TempDir t("house_cli_bounds");
  const std::string good = handHouse(t, "good", "", "");
  ASSERT_EQ(runCli("path --house " + shellQuote(good) + " --from room0:0,0 --to room1:2,2").exitCode, 0);
  struct Case {
    std::string name, from, to, origin, message;
  };
  const std::vector<Case> cases = {
      {"far", "", "", "[4000, 0, 0]", "room 'room0': its map's origin [4000, 0] m lies beyond cells -8192..8192"},
      {"apart", "{x: 3, y: 0,", "{x: 5000, y: -5000,", "[0, 0, 0]",
       "the rooms span 5003 x 5003 cells in the house frame, more than 2048 a side"},
      {"wrapped", "{x: 3, y: 0,", "{x: 2147483647, y: 0,", "[0, 0, 0]",
       "room 'room1': to_house x must be a whole number in -8192..8192, not '2147483647'"},
      {"label", "chair: [1, 1]", "chair: [70000, 1]", "[0, 0, 0]",
       "room 'room0': label 'chair' x must be a whole number in -8192..8192, not '70000'"},
      {"gateway", "cells_a: [[2, 1]]", "cells_a: [[3000, 1]]", "[0, 0, 0]",
       "gateway 0: cells_a [3000, 1] lies outside room 'room0'"},
  };
  for (const Case& c : cases) {
    const std::string dir = handHouse(t, c.name, c.from, c.to, c.origin);
    const RunOutput path = runCli("path --house " + shellQuote(dir) + " --from room0:0,0 --to room1:2,2");
    EXPECT_TRUE(oneLineError(path, c.message)) << c.name << ": " << path.exitCode << " " << path.err;
    const std::string png = t.path(c.name + ".png"), svg = t.path(c.name + ".svg"), ros = t.path(c.name + "-ros");
    const RunOutput ex = runCli("export " + shellQuote(dir) + " --png " + shellQuote(png) + " --svg " +
                                shellQuote(svg) + " --ros " + shellQuote(ros));
    EXPECT_TRUE(oneLineError(ex, c.message)) << c.name << ": " << ex.exitCode << " " << ex.err;
    for (const std::string& out : {png, svg, ros}) EXPECT_FALSE(std::filesystem::exists(out)) << out;
    const RunOutput connect = runCli("connect sim:worlds/houses/three-rooms.map@8,8 --house " + shellQuote(dir));
    EXPECT_TRUE(oneLineError(connect, c.message)) << c.name << ": " << connect.exitCode << " " << connect.err;
  }
}

// The PNG of a large house at many pixels a cell is refused before anything is allocated or written.
TEST(HouseCli, ExportBoundsThePictureSize) {
  TempDir t("house_cli_png");
  // Rooms 2045 cells apart: a house 2048 x 3 cells, the widest accepted (HouseLimits), and one 2048 x 2048.
  const std::string wide = handHouse(t, "wide", "{x: 3, y: 0,", "{x: 2045, y: 0,");
  const std::string square = handHouse(t, "square", "{x: 3, y: 0,", "{x: 2045, y: 2045,");
  const std::string png = t.path("h.png");
  EXPECT_EQ(runCli("export " + shellQuote(wide) + " --png " + shellQuote(png) + " --cell-px 32").exitCode, 0);
  std::filesystem::remove(png);
  EXPECT_TRUE(oneLineError(runCli("export " + shellQuote(square) + " --png " + shellQuote(png) + " --cell-px 5"),
                           "the house is 2048 x 2048 cells; at --cell-px 5 its picture would hold more than 67108864 "
                           "pixels: give a smaller --cell-px"));
  EXPECT_FALSE(std::filesystem::exists(png));
  EXPECT_EQ(runCli("export " + shellQuote(square) + " --png " + shellQuote(png) + " --cell-px 1").exitCode, 0);
}

// CPU seconds (user + system) of the finished child processes so far.
double childCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// HouseExpo plans with numbers or sizes no floor plan has: sim-house gives one line, exit 2, at once.
TEST(HouseCli, HostileHouseExpoPlansAreOneClearMessage) {
  TempDir t("house_cli_expo_bad");
  std::string many = R"({"verts": [)";
  for (int i = 0; i < 20000; ++i) {
    const double a = 2.0 * M_PI * i / 20000.0;
    many += (i ? "," : "") + std::string("[") + std::to_string(6.0 + 5.0 * std::cos(a)) + "," +
            std::to_string(6.0 + 5.0 * std::sin(a)) + "]";
  }
  many += "]}";
  const std::string square = R"("verts": [[0,0],[4,0],[4,4],[0,4]])";
  struct Case {
    std::string file, json, message;
  };
  const std::vector<Case> cases = {
      {"many.json", many, "'verts' holds 20000 points, more than 4096"},
      {"huge.json", R"({"verts": [[1e308,1e308],[1.7e308,1e308],[1e308,1.7e308]]})", "within -1000..1000 m"},
      {"overflow.json", R"({"verts": [[0,0],[1e309,0],[0,1]]})", "not valid JSON"},
      {"boxes.json", "{" + square + R"(, "room_category": {"Kitchen": [[-1e300, -1e300, 1e300, 1e300]]}})",
       "room_category 'Kitchen' holds a box that is not [x1, y1, x2, y2] of numbers within -1000..1000 m"},
  };
  for (const Case& c : cases) {
    const std::string file = t.write(c.file, c.json);
    const double before = childCpuSeconds();
    const RunOutput run = runCli("sim-house " + shellQuote(file) + " --save " + shellQuote(t.path("h")));
    EXPECT_TRUE(oneLineError(run, c.message)) << c.file << ": " << run.exitCode << " " << run.err;
    EXPECT_LT(childCpuSeconds() - before, 2.0) << c.file;  // the whole sanitized process; once 20 CPU minutes
    EXPECT_FALSE(std::filesystem::exists(t.path("h")));
  }
}

}  // namespace
}  // namespace nxtmap::cli::test
