// `nxtmap connect` and `nxtmap flash` from the outside: the real binary, scripted.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>

#include "tests/cli/CliTestSupport.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::cli::test {
namespace {

const char* kWorld = "sim:worlds/seed-appendix-a/occupancy-120.map@1,20";

// Runs `nxtmap <args>` with `script` on stdin.
RunOutput runWithInput(const std::string& args, const std::string& script, const std::string& env = "") {
  static int counter = 0;
  TempDir tmp("console" + std::to_string(counter++));
  const std::string in = tmp.path("in"), out = tmp.path("out"), err = tmp.path("err");
  std::ofstream(in) << script;
  const std::string cmd = "cd " + shellQuote(NXTMAP_SOURCE_DIR) + " && " + env + " " + shellQuote(NXTMAP_CLI_PATH) +
                          " " + args + " < " + shellQuote(in) + " > " + shellQuote(out) + " 2> " + shellQuote(err);
  const int status = std::system(cmd.c_str());
  RunOutput r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(out);
  r.err = readFile(err);
  return r;
}

TEST(Console, ExploresReachesGoalsSavesAndExports) {
  TempDir tmp("consolemap");
  const std::string script =
      "explore\nwait explored 120\ngoto 5 5\nwait goal 60\nlabel chair 11 9\n"
      "goto near chair\nwait goal 60\nsave " +
      tmp.path("room.yaml") + "\nexport " + tmp.path("room.png") + "\nstatus\nquit\n";
  const RunOutput r = runWithInput(std::string("connect ") + kWorld + " --speed 25", script);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("exploring done"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("driving to goto (5,5)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("driving to near chair"), std::string::npos) << r.out;
  EXPECT_GE(std::count(r.out.begin(), r.out.end(), '\n'), 5);
  EXPECT_NE(r.out.find("goal reached"), std::string::npos);
  EXPECT_NE(r.out.find("0 duplicates ignored"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(tmp.path("room.yaml")));
  EXPECT_TRUE(std::filesystem::exists(tmp.path("room.pgm")));
  EXPECT_GT(std::filesystem::file_size(tmp.path("room.png")), 100u);
  EXPECT_NE(readFile(tmp.path("room.yaml")).find("chair"), std::string::npos);
}

// `calibrate` on the stand-in brick: a robot whose turns are 2 % off (nxt-uncalibrated, seed 1: +2.04 %, as
// `sim` prints it beside what it learns) measures them on the spot and says so; `status` then reports them. A
// house mapped afterwards starts from them (it would relearn them from none, to +1.77 % here) and keeps them.
TEST(Console, CalibrateMeasuresTheTurnsWhereTheRobotStands) {
  const RunOutput r = runWithInput(
      "connect sim:worlds/seed-appendix-a/occupancy-120.map@6,14 --robot brick --noise nxt-uncalibrated --speed 25",
      "calibrate 120\nstatus\nexplore house\nwait house 600\nstatus\nquit\n");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string key = "calibrated: turns ";
  const size_t at = r.out.find(key);
  ASSERT_NE(at, std::string::npos) << r.out;
  const double percent = std::stod(r.out.substr(at + key.size()));
  EXPECT_NEAR(percent, 2.04, 0.5) << r.out;
  EXPECT_NE(r.out.find("(before: +0.00 %)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("turns " + r.out.substr(at + key.size(), 5) + " % (learnt)"), std::string::npos) << r.out;
  const std::string after = "turns ";
  const size_t house = r.out.find(after, r.out.find("the house is mapped"));
  ASSERT_NE(house, std::string::npos) << r.out;
  EXPECT_NEAR(std::stod(r.out.substr(house + after.size())), percent, 0.15) << r.out;
  // In the open, nothing to measure by: said so, the error unchanged.
  const RunOutput open = runWithInput(
      "connect sim:worlds/seed-appendix-a/occupancy-120.map@11,11 --robot brick --noise nxt-uncalibrated --speed 25",
      "calibrate 120\nquit\n");
  EXPECT_EQ(open.exitCode, 0) << open.err;
  EXPECT_NE(open.out.find("not calibrated: the turns' error is still +0.00 %"), std::string::npos) << open.out;
}

TEST(Console, BadGoalsAndMalformedCommandsGetOneClearMessageAndTheRobotStays) {
  struct Case {
    std::string line, message;
  };
  const Case cases[] = {
      {"goto 99 99", "nxtmap: goto (99,99): outside the map (22 x 22 cells); nothing sent"},
      {"goto 1 0", "nxtmap: goto (1,0): that cell is an obstacle; nothing sent"},
      {"goto 0 0", "nxtmap: goto (0,0): that cell is unexplored; nothing sent"},
      {"goto 12 9", "nxtmap: goto (12,9): that cell is unexplored; nothing sent"},
      {"goto near sofa", "nxtmap: goto near sofa: no such label (see label NAME C R); nothing sent"},
      {"goto 3", "nxtmap: usage: goto C R  or  goto near LABEL"},
      {"goto -1 4", "nxtmap: column '-1' is not a cell number (0, 1, 2, ...)"},
      {"goto x y", "nxtmap: column 'x' is not a cell number (0, 1, 2, ...)"},
      {"wait goal nan", "nxtmap: wait: SECONDS 'nan' is not a whole number of seconds (0, 1, 2, ...)"},
      {"wait goal 1e300", "nxtmap: wait: SECONDS '1e300' is not a whole number of seconds (0, 1, 2, ...)"},
      {"label 9lives 1 1", "nxtmap: label 9lives: a name is 1..64 letters, digits, _ or -, starting with a letter"},
      {"fly away", "nxtmap: unknown command 'fly' (type help for the list)"},
      {"save", "nxtmap: usage: save DIR  or  save FILE.yaml"},
      {"route 1 2 2", "nxtmap: route 1 2 2: no room '1' (the house has rooms 0..0, see rooms); nothing sent"},
      {"route 0 0 0", "nxtmap: route 0 0 0: that cell is unexplored; nothing sent"},
  };
  std::string script = "explore\nwait explored 120\n";
  for (const Case& c : cases) script += c.line + "\n";
  script += "status\nquit\n";
  const RunOutput r = runWithInput(std::string("connect ") + kWorld + " --speed 25", script);
  EXPECT_EQ(r.exitCode, 2);  // a script with refused commands fails
  const std::vector<std::string> errors = lines(r.err);
  ASSERT_EQ(errors.size(), std::size(cases)) << r.err;
  for (size_t i = 0; i < errors.size(); ++i) EXPECT_EQ(errors[i], cases[i].message);
  // The robot did not move after exploring: exactly one command (explore) ran on the brick.
  EXPECT_NE(r.out.find("1 commands run, 0 duplicates ignored"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("robot: done exploring"), std::string::npos) << r.out;
}

TEST(Console, BadLinksAreClearErrors) {
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"connect usb",
       "nxtmap: connect: link 'usb' has no kind: use bt:00:16:53:XX:XX:XX, serial:/dev/rfcomm0, tcp:HOST:PORT or "
       "sim:WORLD[@COL,ROW]"},
      {"connect bt:00:16:53",
       "nxtmap: connect: Bluetooth address '00:16:53' is not six hex pairs like 00:16:53:0A:1B:2C"},
      {"connect tcp:localhost:99999", "nxtmap: connect: TCP port 99999 is outside 1..65535"},
      {"connect serial:rfcomm0", "nxtmap: connect: serial device 'rfcomm0' must be an absolute path like /dev/rfcomm0"},
      {"connect sim:no/such.map", ""},
      {"connect tcp:127.0.0.1:1 --connect-timeout 1", ""},
  };
  for (const Case& c : cases) {
    const RunOutput r = runWithInput(c.args, "");
    EXPECT_EQ(r.exitCode, 2) << c.args;
    ASSERT_EQ(lines(r.err).size(), 1u) << c.args << ": " << r.err;
    if (!c.message.empty())
      EXPECT_EQ(lines(r.err)[0], c.message);
    else
      EXPECT_EQ(r.err.rfind("nxtmap: connect: ", 0), 0u) << r.err;
  }
}

TEST(Flash, ChecksTheImageAndExplainsAMissingBrick) {
  TempDir tmp("flash");
  const std::string fake = tmp.path("fwflash");
  std::ofstream(fake) << "#!/bin/sh\necho 'Checking firmware... OK.'\necho \"$1\" > " << tmp.path("flashed")
                      << "\nif [ -e " << tmp.path("brick") << " ]; then echo 'Firmware flashed'; exit 0; fi\n"
                      << "echo 'NXT not found. Is it properly plugged in via USB?'\nexit 1\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const std::string env = "NXTMAP_FWFLASH=" + shellQuote(fake);
  std::ofstream(tmp.path("empty.bin")).close();
  std::ofstream(tmp.path("big.bin")) << std::string(262145, 'x');
  std::ofstream(tmp.path("fw.bin")) << std::string(262144, '\0');

  RunOutput r = runWithInput("flash", "", env);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "nxtmap: flash: give either FILE.bin or --restore\n");
  r = runWithInput("flash " + tmp.path("none.bin"), "", env);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(r.err, "nxtmap: flash: " + tmp.path("none.bin") + " is not a file\n");
  r = runWithInput("flash " + tmp.path("empty.bin"), "", env);
  EXPECT_EQ(r.exitCode, 2);
  r = runWithInput("flash " + tmp.path("big.bin"), "", env);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("more than the NXT's 262144 bytes of flash"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("flashed")));  // nothing reached fwflash

  r = runWithInput("flash " + tmp.path("fw.bin"), "", env);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lines(r.err).size(), 1u);
  EXPECT_EQ(r.err.rfind("nxtmap: flash: no NXT brick waiting in SAM-BA mode on USB", 0), 0u) << r.err;

  std::ofstream(tmp.path("brick")).close();
  r = runWithInput("flash " + tmp.path("fw.bin"), "", env);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(tmp.path("flashed")), tmp.path("fw.bin") + "\n");
  r = runWithInput("flash --restore", "", env);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readFile(tmp.path("flashed")), "/usr/share/nxt-firmware/nxt_firmware.bin\n");
}

}  // namespace
}  // namespace nxtmap::cli::test
