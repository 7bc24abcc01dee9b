// Output files of the nxtmap process: a target that cannot be written is refused with one "nxtmap: " line
// and exit 2 before anything is written (a device stays a device); a failed write keeps the old file byte
// for byte and names the reason; /dev/stdout still works; "DIR/" is a legitimate house directory.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"

namespace nxtmap::cli::test {
namespace {
namespace fs = std::filesystem;

const std::string kSim = "sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --show none";

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

bool isCharDevice(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

struct BadTarget {
  std::string args;
  const char* mention;
};

TEST(OutputFiles, TargetsThatCannotBeWrittenAreOneLineAndNothingChanges) {
  TempDir t("out_bad");
  fs::create_directories(t.path("folder"));
  const std::string missing = t.path("missing");
  std::vector<BadTarget> cases = {
      {kSim + " --png " + shellQuote(t.path("folder")), "it is a directory"},
      {kSim + " --png " + shellQuote(missing + "/x.png"), "does not exist"},
      {kSim + " --save " + shellQuote(missing + "/x.yaml"), "does not exist"},
      {"experiments worlds/seed-appendix-a --markdown " + shellQuote(missing + "/r.md"), "does not exist"},
      {"experiments worlds/seed-appendix-a --csv " + shellQuote(t.path("folder")), "it is a directory"},
      {"sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(missing + "/h"), "does not exist"},
      {"sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(missing + "/h/"), "does not exist"},
  };
  const bool devFull = isCharDevice("/dev/full");  // not in every chroot
  if (devFull) {
    cases.push_back({kSim + " --png /dev/full", "it is a device"});
    cases.push_back({"experiments worlds/seed-appendix-a --csv /dev/full", "it is a device"});
  }
  for (const BadTarget& c : cases) {
    SCOPED_TRACE("nxtmap " + c.args);
    const RunOutput r = runCli(c.args);
    EXPECT_EQ(r.exitCode, 2);
    const std::vector<std::string> errLines = lines(r.err);
    ASSERT_EQ(errLines.size(), 1u) << r.err;
    EXPECT_EQ(errLines[0].rfind("nxtmap: ", 0), 0u) << errLines[0];
    EXPECT_NE(errLines[0].find(c.mention), std::string::npos) << errLines[0];
    EXPECT_EQ(r.out, "") << "refused before the run";
  }
  if (devFull) {
    EXPECT_TRUE(isCharDevice("/dev/full"));
  }
  EXPECT_EQ(entries(t.path()), std::vector<std::string>{"folder"});
  EXPECT_TRUE(fs::is_empty(t.path("folder")));
}

TEST(OutputFiles, AFailedPngRewriteKeepsTheOldPictureByteForByte) {
  TempDir t("out_png");
  const std::string png = t.path("map.png");
  ASSERT_EQ(runCli(kSim + " --png " + shellQuote(png)).exitCode, 0);
  const std::string good = readFile(png);
  ASSERT_GT(good.size(), 600u);
  // The same picture again, with files limited to 512 bytes (SIGXFSZ ignored: the write fails with EFBIG).
  // Output goes through a pipe so only the picture meets the limit.
  const std::string cmd = "cd " + shellQuote(NXTMAP_SOURCE_DIR) + " && (trap '' XFSZ; ulimit -f 1; " +
                          shellQuote(NXTMAP_CLI_PATH) + " " + kSim + " --png " + shellQuote(png) +
                          " 2>&1 < /dev/null; echo \"exit $?\") | cat > " + shellQuote(t.path("log"));
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string log = readFile(t.path("log"));
  EXPECT_NE(log.find("\nexit 2\n"), std::string::npos) << log;
  EXPECT_NE(log.find("nxtmap: cannot write " + png + ": File too large\n"), std::string::npos) << log;
  EXPECT_EQ(readFile(png), good);
  EXPECT_EQ(entries(t.path()), (std::vector<std::string>{"log", "map.png"})) << "no temporary file left";
}

TEST(OutputFiles, APngToStdoutStillWorks) {
  const RunOutput r = runCli(kSim + " --png /dev/stdout");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\x89PNG\r\n"), std::string::npos);
}

TEST(OutputFiles, AHouseSavedAsDirWithATrailingSlash) {
  TempDir t("out_slash");
  for (int i = 0; i < 2; ++i) {  // a new house, then one replaced
    const RunOutput r =
        runCli("sim-house worlds/houses/three-rooms.map --start 8,8 --save " + shellQuote(t.path("h") + "/"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(t.path("h/house.yaml")));
    EXPECT_EQ(entries(t.path()), std::vector<std::string>{"h"}) << "no staging directory left";
  }
}

}  // namespace
}  // namespace nxtmap::cli::test
