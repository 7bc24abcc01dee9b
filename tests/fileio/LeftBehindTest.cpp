// LeftBehind: what a killed writer left beside its target is recognised by name and removed by the next
// writer of the same target, when its process is gone; a live writer's entries and other targets' stay.
#include "host/fileio/LeftBehind.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "host/fileio/AtomicFile.hpp"
#include "tests/support/EndedPid.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

TEST(LeftBehind, WriterPidsAreReadFromTheirNames) {
  struct Row {
    std::string entry, name, infix;
    pid_t pid;
  };
  const Row rows[] = {
      {"house.saving-123", "house", ".saving-", 123}, {"map.png.tmp-77-0", "map.png", ".tmp-", 77},
      {"map.png.tmp-77-12", "map.png", ".tmp-", 77},  {"map.png.tmp-77", "map.png", ".tmp-", 77},
      {"map.png.tmp-", "map.png", ".tmp-", 0},        {"map.png.tmp-x-1", "map.png", ".tmp-", 0},
      {"other.png.tmp-77-0", "map.png", ".tmp-", 0},  {"map.png", "map.png", ".tmp-", 0},
      {"house.saving-0", "house", ".saving-", 0},     {"house.saving-99999999999", "house", ".saving-", 0},
      {"house.saving-12a", "house", ".saving-", 0},   {"map.png.tmp-77-0", "map", ".tmp-", 0},
  };
  for (const Row& r : rows) EXPECT_EQ(writerPid(r.entry, r.name, r.infix), r.pid) << r.entry;
}

TEST(LeftBehind, TheNextWriteRemovesTheTemporaryFilesOfKilledWriters) {
  TempDir t("left_behind");
  const pid_t gone = test::endedPid();
  const std::string stale = t.write("map.png.tmp-" + std::to_string(gone) + "-0", "half a picture");
  const std::string live = t.write("map.png.tmp-1-0", "pid 1 is alive");  // init: never ours to remove
  const std::string other = t.write("other.png.tmp-" + std::to_string(gone) + "-0", "another target's");
  std::string error;
  ASSERT_TRUE(writeFileAtomically(t.path("map.png"), "picture", error)) << error;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
}

}  // namespace
}  // namespace nxtmap::fileio
