// AtomicFile and OutputTarget: an output is written whole or not at all, a refused or failed write
// leaves the target as it was (a device stays a device), and the error names the reason.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "tests/support/FileSizeLimit.hpp"
#include "tests/support/FileText.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;
using test::TempDir;

TEST(AtomicFile, WritesANewFileAndReplacesAnOldOneKeepingItsMode) {
  TempDir t("atomic_ok");
  std::string error;
  ASSERT_TRUE(writeFileAtomically(t.path("a.txt"), "first", error)) << error;
  EXPECT_EQ(test::readWholeFile(t.path("a.txt")), "first");
  ASSERT_EQ(::chmod(t.path("a.txt").c_str(), 0640), 0);
  ASSERT_TRUE(writeFileAtomically(t.path("a.txt"), "second, longer", error)) << error;
  EXPECT_EQ(test::readWholeFile(t.path("a.txt")), "second, longer");
  EXPECT_EQ(fs::status(t.path("a.txt")).permissions(), fs::perms(0640));
  EXPECT_EQ(test::folderEntries(t.path()), std::vector<std::string>{"a.txt"});
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileByteForByteAndSaysWhy) {
  TempDir t("atomic_fail");
  const std::string old(3000, 'o');
  const std::string target = t.write("keep.bin", old);
  std::string error;
  {
    const test::FileSizeLimit limit(4096);
    EXPECT_FALSE(writeFileAtomically(target, std::string(64 * 1024, 'n'), error));
  }
  EXPECT_EQ(test::readWholeFile(target), old);
  EXPECT_NE(error.find(target), std::string::npos) << error;
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(test::folderEntries(t.path()), std::vector<std::string>{"keep.bin"}) << "the temporary file is removed";
}

TEST(AtomicFile, AnUncommittedFileLeavesNoTrace) {
  TempDir t("atomic_abandon");
  const std::string target = t.write("keep.txt", "old");
  {
    AtomicFile f;
    std::string error;
    ASSERT_TRUE(f.open(target, error)) << error;
    ASSERT_TRUE(f.write(std::string("new"), error)) << error;
    EXPECT_TRUE(fs::exists(f.tempPath()));
  }
  EXPECT_EQ(test::readWholeFile(target), "old");
  EXPECT_EQ(test::folderEntries(t.path()), std::vector<std::string>{"keep.txt"});
}

struct RefusedCase {
  const char* name;
  std::string path;
  const char* reason;
};

TEST(OutputTarget, TargetsThatAreNotRegularFilesAreRefusedAndLeftAsTheyWere) {
  TempDir t("atomic_refuse");
  fs::create_directories(t.path("folder"));
  ASSERT_EQ(::mkfifo(t.path("pipe").c_str(), 0600), 0);
  fs::create_symlink(t.path("nothing"), t.path("dangling"));
  struct stat before {};
  const bool haveDevFull = ::stat("/dev/full", &before) == 0 && S_ISCHR(before.st_mode);  // not in every chroot
  std::vector<RefusedCase> cases = {
      {"a directory", t.path("folder"), "it is a directory"},
      {"a pipe", t.path("pipe"), "it is a pipe"},
      {"a folder name", t.path("folder") + "/", "names a folder"},
      {"a missing folder", t.path("missing/deeper/x.png"), "does not exist"},
      {"a file as the folder", t.path("pipe/x.png"), "Not a directory"},
      {"a symbolic link to nothing", t.path("dangling"), "symbolic link to nothing"},
      {"no name", "", "no file name"},
  };
  if (haveDevFull) cases.push_back({"a device", "/dev/full", "it is a device"});
  const std::vector<std::string> namesBefore = test::folderEntries(t.path());
  for (const RefusedCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::string error;
    EXPECT_FALSE(writeFileAtomically(c.path, "data", error));
    EXPECT_EQ(error.rfind("cannot write " + c.path, 0), 0u) << error;
    EXPECT_NE(error.find(c.reason), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  struct stat after {};
  if (haveDevFull) {
    ASSERT_EQ(::stat("/dev/full", &after), 0);
    EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/full is still the device";
    EXPECT_EQ(after.st_rdev, before.st_rdev);
  }
  EXPECT_EQ(test::folderEntries(t.path()), namesBefore) << "nothing created, nothing removed";
  EXPECT_TRUE(fs::is_directory(t.path("folder")));
  EXPECT_TRUE(fs::is_empty(t.path("folder")));
}

TEST(OutputTarget, ASymbolicLinkToAFileStaysALink) {
  TempDir t("atomic_link");
  const std::string real = t.write("real.txt", "old");
  fs::create_symlink(real, t.path("link.txt"));
  std::string error;
  ASSERT_TRUE(writeFileAtomically(t.path("link.txt"), "new", error)) << error;
  EXPECT_TRUE(fs::is_symlink(t.path("link.txt")));
  EXPECT_EQ(test::readWholeFile(real), "new");
}

TEST(OutputTarget, StandardStreamsAreWrittenInPlace) {
  const std::optional<OutputTarget> out = [] {
    std::string error;
    return resolveOutputTarget("/dev/stdout", error);
  }();
  ASSERT_TRUE(out);
  EXPECT_EQ(out->streamFd, 1);
}

// A disk that is really full: a 32 KiB tmpfs mounted in a private mount namespace of a child process
// (needs the privilege to mount; skipped without it). The child reports the error text through a pipe.
TEST(AtomicFile, AFullDiskIsNamedAsTheReason) {
  TempDir t("atomic_full");
  const std::string mountPoint = t.path("small");
  fs::create_directories(mountPoint);
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(fds[0]);
    std::string report = "skip";
    if (::unshare(CLONE_NEWNS) == 0 && ::mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0 &&
        ::mount("tmpfs", mountPoint.c_str(), "tmpfs", 0, "size=32k") == 0) {
      const std::string target = mountPoint + "/keep.bin";
      std::ofstream(target, std::ios::binary) << "old bytes";
      std::string error;
      const bool ok = writeFileAtomically(target, std::string(256 * 1024, 'n'), error);
      const bool kept = test::readWholeFile(target) == "old bytes" &&
                        test::folderEntries(mountPoint) == std::vector<std::string>{"keep.bin"};
      report = std::string(ok ? "written" : kept ? "kept" : "damaged") + "|" + error;
    }
    const ssize_t n = ::write(fds[1], report.data(), report.size());
    ::_exit(n == static_cast<ssize_t>(report.size()) ? 0 : 1);
  }
  ::close(fds[1]);
  std::string report;
  char buf[512];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) report.append(buf, static_cast<size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  if (report == "skip") GTEST_SKIP() << "no privilege to mount a small tmpfs";
  EXPECT_EQ(report.substr(0, report.find('|')), "kept") << report;
  EXPECT_NE(report.find("No space left on device"), std::string::npos) << report;
}

}  // namespace
}  // namespace nxtmap::fileio
