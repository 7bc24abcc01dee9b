#include "host/fileio/AtomicFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <optional>

#include "host/fileio/LeftBehind.hpp"
#include "host/fileio/OutputTarget.hpp"

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;

constexpr int kMaxTempAttempts = 1000;       // unique names tried before giving up
constexpr const char* kTempInfix = ".tmp-";  // "<target>.tmp-<pid>-<n>"

std::string folderOf(const std::string& file) {
  const fs::path p(file);
  return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

}  // namespace

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() {
  if (fd_ >= 0 && !stream_) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

bool AtomicFile::fail(const std::string& why, std::string& error) {
  discard();
  error = "cannot write " + shown_ + ": " + why;
  return false;
}

bool AtomicFile::open(const std::string& target, std::string& error) {
  discard();
  shown_ = target;
  const std::optional<OutputTarget> t = resolveOutputTarget(target, error);
  if (!t) return false;
  target_ = t->file;
  stream_ = t->streamFd >= 0;
  if (stream_) {
    fd_ = t->streamFd;
    return true;
  }
  removeLeftBehind(target_, kTempInfix, false);  // temporary files of killed writers of this target
  const std::string base = target_ + kTempInfix + std::to_string(::getpid()) + "-";
  for (int n = 0; n < kMaxTempAttempts; ++n) {
    const std::string candidate = base + std::to_string(n);
    fd_ = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      temp_ = candidate;
      if (t->exists) ::fchmod(fd_, static_cast<mode_t>(t->mode));  // the new file keeps the old one's mode
      return true;
    }
    if (errno != EEXIST) return fail(systemErrorText(errno), error);
  }
  return fail("no free temporary file name beside it", error);
}

bool AtomicFile::write(const void* data, size_t size, std::string& error) {
  if (fd_ < 0) return fail("the file is not open", error);
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return fail(systemErrorText(n < 0 ? errno : EIO), error);
    p += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool AtomicFile::commit(std::string& error) {
  if (fd_ < 0) return fail("the file is not open", error);
  if (stream_) {
    fd_ = -1;
    return true;
  }
  if (::fsync(fd_) != 0) return fail(systemErrorText(errno), error);
  const int closed = ::close(fd_);
  fd_ = -1;
  if (closed != 0) return fail(systemErrorText(errno), error);
  if (::rename(temp_.c_str(), target_.c_str()) != 0) return fail(systemErrorText(errno), error);
  temp_.clear();
  std::string ignored;
  syncDirectory(folderOf(target_), ignored);  // best effort: the new file is in place either way
  return true;
}

bool writeFileAtomically(const std::string& target, const std::string& bytes, std::string& error) {
  AtomicFile f;
  return f.open(target, error) && f.write(bytes, error) && f.commit(error);
}

bool syncDirectory(const std::string& folder, std::string& error) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) {
    error = folder + ": " + systemErrorText(errno);
    return false;
  }
  const bool ok = ::fsync(fd) == 0;
  if (!ok) error = folder + ": " + systemErrorText(errno);
  ::close(fd);
  return ok;
}

}  // namespace nxtmap::fileio
