// StagingDirectory: a directory replaced whole; "DIR/" names DIR; a missing folder is refused and nothing
// is created; staging directories left by killed processes are removed by the next save of the same target.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/StagingDirectory.hpp"
#include "tests/support/EndedPid.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

TEST(StagingDirectory, TargetsDropTrailingSlashes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"out/house", "out/house"}, {"out/house/", "out/house"}, {"out/house//", "out/house"},
      {"house/", "house"},        {"./house/", "house"},       {"/tmp/h/", "/tmp/h"},
  };
  for (const auto& [given, expected] : cases) EXPECT_EQ(directoryTarget(given).string(), expected) << given;
}

TEST(StagingDirectory, ReplacesTheTargetWholeAndLeavesNoStaging) {
  TempDir t("stage_ok");
  for (const char* content : {"first", "second"}) {
    StagingDirectory stage;
    std::string error;
    ASSERT_TRUE(stage.open(t.path("dir") + "/", error)) << error;
    ASSERT_TRUE(writeFileAtomically((stage.path() / "f.txt").string(), content, error)) << error;
    ASSERT_TRUE(stage.commit(error)) << error;
    std::ifstream in(t.path("dir/f.txt"));
    std::string got;
    std::getline(in, got);
    EXPECT_EQ(got, content);
  }
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(t.path())) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"dir"});
}

TEST(StagingDirectory, AMissingFolderIsRefusedAndNothingIsCreated) {
  TempDir t("stage_missing");
  for (const std::string& dir : {t.path("no/such/dir"), t.path("no/such/dir/"), std::string("."), std::string("/")}) {
    StagingDirectory stage;
    std::string error;
    EXPECT_FALSE(stage.open(dir, error)) << dir;
    EXPECT_EQ(error.rfind("cannot save " + dir + ": ", 0), 0u) << error;
  }
  std::string error;
  StagingDirectory stage;
  ASSERT_FALSE(stage.open(t.path("no/such/dir"), error));
  EXPECT_NE(error.find("the folder " + t.path("no/such") + " does not exist"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_empty(t.path()));
}

TEST(StagingDirectory, StaleStagingOfDeadProcessesIsRemovedByTheNextSave) {
  TempDir t("stage_stale");
  const std::string dead = t.path("dir.saving-" + std::to_string(test::endedPid()));
  const std::string alive = t.path("dir.saving-1");  // pid 1 lives as long as the system
  const std::string otherTarget = t.path("other.saving-" + std::to_string(test::endedPid()));
  for (const std::string& d : {dead, alive, otherTarget}) t.write(fs::path(d).filename().string() + "/x", "x");
  StagingDirectory stage;
  std::string error;
  ASSERT_TRUE(stage.open(t.path("dir"), error)) << error;
  ASSERT_TRUE(stage.commit(error)) << error;
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(alive)) << "a live process's staging is not touched";
  EXPECT_TRUE(fs::exists(otherTarget)) << "another target's staging is not touched";
  EXPECT_TRUE(fs::is_directory(t.path("dir")));
}

}  // namespace
}  // namespace nxtmap::fileio
