// Bad worlds, images and firmware files, and nonsense numbers, given to the nxtmap binary (issue 15, defects
// 1, 6, 7 and 11): each gets one "nxtmap: " line and exit code 2, at once (devices are never read).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kRoom = "worlds/seed-appendix-a/occupancy-089.map";  // 22 x 22, start 1,20 free
// A refusal comes at once (under ASan well within a second or two); a run still going after this is a hang
// (a device read for ever) and is killed.
constexpr int kKillAfterS = 20;

// A 4 x 3 room: walls around two free cells (1,1) and (2,1).
const std::string kPgm =
    std::string("P5\n4 3\n255\n") + std::string(4, '\0') + '\0' + '\xfe' + '\xfe' + '\0' + std::string(4, '\0');

std::string rosYaml(const std::string& replace) {
  std::string y =
      "image: room.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
      "free_thresh: 0.196\n";
  const std::string key = replace.substr(0, replace.find(':') + 1);
  const size_t at = y.find(key);
  if (at == std::string::npos) return y + replace + "\n";
  return y.replace(at, y.find('\n', at) - at, replace);
}

// Writes room.pgm and w.yaml (with `line` replacing its key's line) into the directory.
std::function<void(const TempDir&)> ros(const std::string& line) {
  return [line](const TempDir& d) {
    d.write("room.pgm", kPgm);
    d.write("w.yaml", rosYaml(line));
  };
}

std::function<void(const TempDir&)> link(const std::string& target, const std::string& name,
                                         const std::string& yamlLine = "") {
  return [=](const TempDir& d) {
    std::filesystem::create_symlink(target, d.path(name));
    if (!yamlLine.empty()) d.write("w.yaml", rosYaml(yamlLine));
  };
}

std::function<void(const TempDir&)> folder(const std::string& name, const std::string& yamlLine = "") {
  return [=](const TempDir& d) {
    std::filesystem::create_directories(d.path(name));
    if (!yamlLine.empty()) d.write("w.yaml", rosYaml(yamlLine));
  };
}

struct BadCall {
  std::string name;
  std::string args;  // "{dir}" stands for the case's temporary directory
  std::function<void(const TempDir&)> setup;
  std::string expected;  // part of the one line
};

std::vector<BadCall> worldCases() {
  const auto none = [](const TempDir&) {};
  struct World {
    std::string name, file;
    std::function<void(const TempDir&)> setup;
    std::string expected;
  };
  const std::vector<World> worlds = {
      {"resolutionTiny", "w.yaml", ros("resolution: 0.004"), "'resolution' 0.004 is out of range"},
      {"resolutionDenormal", "w.yaml", ros("resolution: 1e-300"), "'resolution' 1e-300 is out of range"},
      {"resolutionHuge", "w.yaml", ros("resolution: 1e300"), "'resolution' 1e+300 is out of range"},
      {"resolutionZero", "w.yaml", ros("resolution: 0"), "'resolution' must be a number > 0"},
      {"resolutionNegative", "w.yaml", ros("resolution: -0.1"), "'resolution' must be a number > 0"},
      {"resolutionNan", "w.yaml", ros("resolution: .nan"), "'resolution' must be a number > 0"},
      {"originNan", "w.yaml", ros("origin: [.nan, 0.0, 0.0]"), "'origin' must be [x, y, yaw]"},
      {"originFar", "w.yaml", ros("origin: [1e300, 0.0, 0.0]"), "'origin' [1e+300, 0, 0] is out of range"},
      {"mapDevZero", "zero.map", link("/dev/zero", "zero.map"), "zero.map: is a device, not a regular file"},
      {"yamlDevZero", "zero.yaml", link("/dev/zero", "zero.yaml"), "zero.yaml: is a device, not a regular file"},
      {"imageDevZero", "w.yaml", link("/dev/zero", "zero.pgm", "image: zero.pgm"), "zero.pgm: is a device"},
      {"imageFolder", "w.yaml", folder("pictures", "image: pictures"), "pictures: is a directory, not a file"},
      {"mapFolder", "room.map", folder("room.map"), "room.map: is a directory, not a file"},
      {"yamlFolder", "room.yaml", folder("room.yaml"), "room.yaml: is a directory, not a file"},
      {"missing", "none.map", none, "none.map: cannot open file (No such file or directory)"},
  };
  std::vector<BadCall> out;
  for (const World& w : worlds) {
    const std::string file = "{dir}/" + w.file;
    out.push_back({"sim_" + w.name, "sim " + file + " --start 1,1 --show none", w.setup, w.expected});
    out.push_back({"simHouse_" + w.name, "sim-house " + file + " --start 1,1", w.setup, w.expected});
    out.push_back({"path_" + w.name, "path " + file + " --from 1,1 --to 2,1 --draw never", w.setup, w.expected});
  }
  for (const World& w : worlds) {
    if (w.name != "mapDevZero" && w.name != "mapFolder" && w.name != "resolutionTiny") continue;
    out.push_back({"emulate_" + w.name, "emulate {dir}/" + w.file + " --start 1,1 --seconds 1", w.setup, w.expected});
  }
  return out;
}

std::vector<BadCall> otherCases() {
  const auto none = [](const TempDir&) {};
  const std::string path = "path " + kRoom + " --from 1,20 --to 2,20 --draw never --max-nodes ";
  const std::string maxNodes = "--max-nodes: must be a whole number 1..1000000000000, not ";
  return {
      {"sim_rangeShorterThanACellAndAHalf", "sim {dir}/w.yaml --start 1,1 --show none --robot brick --range-m 0.2",
       ros("resolution: 0.5"), "--range-m 0.2 reaches less than 1.5 of the robot's 20 cm cells"},
      {"simHouse_rangeShorterThanACellAndAHalf", "sim-house {dir}/w.yaml --start 1,1 --robot brick --range-m 0.2",
       ros("resolution: 0.5"),
       "--range-m 0.2 reaches less than 1.5 of the robot's 20 cm cells, so no reading could prove a neighbouring cell "
       "free: use --range-m 0.30 or more"},
      {"emulate_firmwareDevZero", "emulate " + kRoom + " --start 1,20 --seconds 1 --firmware {dir}/fw.elf",
       link("/dev/zero", "fw.elf"), "fw.elf: is a device, not a regular file"},
      {"emulate_firmwareFolder", "emulate " + kRoom + " --start 1,20 --seconds 1 --firmware {dir}/fw.elf",
       folder("fw.elf"), "fw.elf: is a directory, not a file"},
      {"path_maxNodesNegative", path + "-1", none, maxNodes + "'-1'"},
      {"path_maxNodesOverflow", path + "99999999999999999999", none, maxNodes},
      {"path_maxNodesAboveLimit", path + "1000000000001", none, maxNodes},
      {"path_maxNodesHex", path + "0x10", none, maxNodes},
      {"path_maxNodesText", path + "nan", none, maxNodes},
      {"path_maxNodesZero", path + "0", none, maxNodes + "'0' (leave it out for no limit)"},
  };
}

std::string substituteDir(std::string args, const std::string& dir) {
  for (size_t at = args.find("{dir}"); at != std::string::npos; at = args.find("{dir}", at + dir.size())) {
    args.replace(at, 5, dir);
  }
  return args;
}

void expectRefused(const BadCall& c) {
  SCOPED_TRACE(c.name);
  TempDir tmp("badworld_" + c.name);
  c.setup(tmp);
  const std::string args = substituteDir(c.args, tmp.path());
  const RunOutput r = runCli(args, kKillAfterS);
  EXPECT_EQ(r.exitCode, 2) << "nxtmap " << args << "\n" << r.err;
  const std::vector<std::string> errLines = lines(r.err);
  ASSERT_EQ(errLines.size(), 1u) << "nxtmap " << args << "\n" << r.err;
  EXPECT_EQ(errLines[0].rfind("nxtmap: ", 0), 0u) << errLines[0];
  EXPECT_NE(errLines[0].find(c.expected), std::string::npos) << "nxtmap " << args << "\n" << errLines[0];
}

TEST(CliBadWorld, EveryLoaderRefusesWithOneLineAndExitTwo) {
  for (const BadCall& c : worldCases()) expectRefused(c);
}

TEST(CliBadWorld, UnusableResolutionsFirmwareFilesAndCounts) {
  for (const BadCall& c : otherCases()) expectRefused(c);
}

// The world's cells are the world's, the robot's the robot's: a ROS map of any resolution it allows is traced
// at its own cells and the (published, 10 cm) robot maps it on its own grid; the planner uses it as it is.
TEST(CliBadWorld, AnyRosResolutionIsSimulatedOnTheRobotsOwnCells) {
  for (const std::string res : {"0.01", "0.025", "0.125", "0.5"}) {
    SCOPED_TRACE(res);
    TempDir tmp("badworld_res");
    ros("resolution: " + res)(tmp);
    const RunOutput sim = runCli("sim " + shellQuote(tmp.path("w.yaml")) + " --start 1,1 --show none");
    EXPECT_EQ(sim.exitCode, 0) << sim.err;
    EXPECT_NE(sim.out.find("cells of 10 cm, robot published"), std::string::npos) << sim.out;
  }
  TempDir tmp("badworld_plan");
  ros("resolution: 0.025")(tmp);
  const RunOutput r = runCli("path " + shellQuote(tmp.path("w.yaml")) + " --from 1,1 --to 2,1 --draw never");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("length           1 cells ("), std::string::npos) << r.out;
  const RunOutput limit = runCli("path " + kRoom + " --from 1,20 --to 20,1 --draw never --max-nodes 1000000000000");
  EXPECT_EQ(limit.exitCode, 0) << limit.err;
}

}  // namespace
}  // namespace nxtmap::cli::test
