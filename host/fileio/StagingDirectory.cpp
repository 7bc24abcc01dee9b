#include "host/fileio/StagingDirectory.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/LeftBehind.hpp"
#include "host/fileio/OutputTarget.hpp"

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;

constexpr const char* kStagingInfix = ".saving-";

fs::path folderOf(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

}  // namespace

fs::path directoryTarget(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  while (!p.empty() && !p.has_filename() && p.has_relative_path()) p = p.parent_path();
  return p;
}

StagingDirectory::~StagingDirectory() {
  std::error_code ignored;
  if (!stage_.empty()) fs::remove_all(stage_, ignored);
}

bool StagingDirectory::fail(const std::string& why, std::string& error) {
  std::error_code ignored;
  if (!stage_.empty()) fs::remove_all(stage_, ignored);
  stage_.clear();
  error = "cannot save " + shown_ + ": " + why;
  return false;
}

void StagingDirectory::removeStaleSiblings() const { removeLeftBehind(target_, kStagingInfix, true); }

bool checkDirectoryTarget(const std::string& dir, std::string& error) {
  const fs::path target = directoryTarget(dir);
  const std::string name = target.filename().string();
  std::string why;
  struct stat st {};
  if (name.empty() || name == "." || name == "..") {
    why = "name the directory to save into";
  } else if (::stat(folderOf(target).c_str(), &st) != 0) {
    why = errno == ENOENT ? "the folder " + folderOf(target).string() + " does not exist" : systemErrorText(errno);
  } else if (!S_ISDIR(st.st_mode)) {
    why = folderOf(target).string() + " is not a folder";
  }
  if (why.empty()) return true;
  error = "cannot save " + dir + ": " + why;
  return false;
}

bool StagingDirectory::open(const std::string& dir, std::string& error) {
  shown_ = dir;
  target_ = directoryTarget(dir);
  stage_.clear();
  if (!checkDirectoryTarget(dir, error)) return false;
  removeStaleSiblings();
  const fs::path stage = folderOf(target_) / (target_.filename().string() + kStagingInfix + std::to_string(::getpid()));
  if (::mkdir(stage.c_str(), 0777) != 0) return fail(stage.string() + ": " + systemErrorText(errno), error);
  stage_ = stage;
  return true;
}

bool StagingDirectory::commit(std::string& error) {
  if (stage_.empty()) return fail("nothing staged", error);
  std::string why;
  if (!syncDirectory(stage_.string(), why)) return fail(why, error);
  struct stat st {};
  const bool replace = ::lstat(target_.c_str(), &st) == 0;
  const int moved = replace ? ::renameat2(AT_FDCWD, stage_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE)
                            : ::rename(stage_.c_str(), target_.c_str());
  if (moved != 0) return fail(systemErrorText(errno), error);
  syncDirectory(folderOf(target_).string(), why);  // best effort: the new directory is in place either way
  if (!replace) stage_.clear();
  std::error_code ignored;
  if (!stage_.empty()) fs::remove_all(stage_, ignored);  // the old content, after an exchange
  stage_.clear();
  return true;
}

}  // namespace nxtmap::fileio
