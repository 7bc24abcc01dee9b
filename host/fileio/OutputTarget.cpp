#include "host/fileio/OutputTarget.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <filesystem>
#include <system_error>

namespace nxtmap::fileio {
namespace {
namespace fs = std::filesystem;

std::optional<OutputTarget> refuse(const std::string& path, const std::string& why, std::string& error) {
  error = "cannot write " + path + ": " + why;
  return std::nullopt;
}

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "it is a directory";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device, not a regular file";
  if (S_ISFIFO(mode)) return "it is a pipe, not a regular file";
  return "it is not a regular file";
}

// The folder a new file `path` goes in must exist; "" when it does, else the reason.
std::string folderProblem(const fs::path& file) {
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) {
    if (errno == ENOENT) return "the folder " + folder.string() + " does not exist";
    return folder.string() + ": " + systemErrorText(errno);
  }
  if (!S_ISDIR(st.st_mode)) return folder.string() + " is not a folder";
  return "";
}

}  // namespace

std::string systemErrorText(int errorNumber) { return std::error_code(errorNumber, std::generic_category()).message(); }

std::optional<OutputTarget> resolveOutputTarget(const std::string& path, std::string& error) {
  OutputTarget t;
  if (path == "/dev/stdout" || path == "/dev/stderr") {
    t.file = path;
    t.streamFd = path == "/dev/stdout" ? 1 : 2;
    return t;
  }
  if (path.empty()) return refuse("''", "no file name", error);
  if (path.back() == '/') return refuse(path, "it names a folder, not a file", error);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) return refuse(path, systemErrorText(errno), error);
    struct stat link {};
    if (::lstat(path.c_str(), &link) == 0) return refuse(path, "it is a symbolic link to nothing", error);
    const std::string problem = folderProblem(fs::path(path));
    if (!problem.empty()) return refuse(path, problem, error);
    t.file = path;
    return t;
  }
  if (!S_ISREG(st.st_mode)) return refuse(path, kindOf(st.st_mode) + ": not overwritten", error);
  std::error_code ec;
  t.file = fs::is_symlink(fs::symlink_status(path, ec)) ? fs::canonical(path, ec).string() : path;
  if (ec) return refuse(path, ec.message(), error);
  t.exists = true;
  t.mode = static_cast<unsigned>(st.st_mode & 07777);
  return t;
}

}  // namespace nxtmap::fileio
