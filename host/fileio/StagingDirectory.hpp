// StagingDirectory: a directory that is replaced whole or not at all.
//
// open() creates a fresh sibling TARGET.saving-<pid> (the target's folder must exist; nothing else is
// created) after removing the staging siblings that killed saves of the same target left behind (those
// of processes no longer alive). The caller writes its files into path() (AtomicFile flushes each);
// commit() flushes the staging directory, moves it over the target in one rename (an atomic exchange
// when the target exists), flushes the parent folder and removes the old content. A crash at any point
// leaves the old directory or the new one, never a mixture. Destroyed without commit(), the staging
// directory is removed.
#pragma once

#include <filesystem>
#include <string>

namespace nxtmap::fileio {

// `dir` as a directory target: lexically normal, trailing slashes dropped ("out/house/" -> "out/house").
std::filesystem::path directoryTarget(const std::string& dir);
// False with `error` ("cannot save DIR: <reason>") when `dir` names no directory ("", ".", "/") or the
// folder it goes in does not exist. Creates nothing.
bool checkDirectoryTarget(const std::string& dir, std::string& error);

class StagingDirectory {
 public:
  StagingDirectory() = default;
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  // False with `error` ("cannot save DIR: <reason>") when the target's folder is missing or the
  // staging directory cannot be made.
  bool open(const std::string& dir, std::string& error);
  const std::filesystem::path& path() const { return stage_; }
  bool commit(std::string& error);

 private:
  bool fail(const std::string& why, std::string& error);
  void removeStaleSiblings() const;

  std::string shown_;             // the target as the caller named it (for messages)
  std::filesystem::path target_;  // normalised target
  std::filesystem::path stage_;   // the staging directory; empty when none
};

}  // namespace nxtmap::fileio
