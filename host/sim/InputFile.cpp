#include "host/sim/InputFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace nxtmap::sim {
namespace {

// Owns an open descriptor; closes it when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string reason(int errorNumber) { return std::string(" (") + std::strerror(errorNumber) + ")"; }

// "N bytes" for small bounds, "N MiB" for whole mebibytes.
std::string sizeText(size_t bytes) {
  constexpr size_t kMiB = size_t{1} << 20;
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// Why a file of this type cannot be read as input, or "" for a regular file.
std::string typeProblem(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISFIFO(mode)) return "is a pipe, not a regular file";
  return "is not a regular file";
}

}  // namespace

std::optional<std::string> readInputFile(const std::string& path, size_t maxBytes, const std::string& what,
                                         std::string& error) {
  const Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
  if (fd.get() < 0) {
    error = path + ": cannot open " + what + reason(errno);
    return std::nullopt;
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) {
    error = path + ": cannot open " + what + reason(errno);
    return std::nullopt;
  }
  if (const std::string problem = typeProblem(st.st_mode); !problem.empty()) {
    error = path + ": " + problem;
    return std::nullopt;
  }
  const std::string tooLarge = path + ": larger than " + sizeText(maxBytes) + ", the largest " + what + " accepted";
  if (st.st_size < 0 || static_cast<unsigned long long>(st.st_size) > maxBytes) {
    error = tooLarge;
    return std::nullopt;
  }
  std::string bytes;
  bytes.reserve(static_cast<size_t>(st.st_size));
  char chunk[64 * 1024];
  for (;;) {
    const ssize_t n = ::read(fd.get(), chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = path + ": cannot read " + what + reason(errno);
      return std::nullopt;
    }
    if (n == 0) return bytes;
    if (static_cast<size_t>(n) > maxBytes - bytes.size()) {  // it grew since fstat
      error = tooLarge;
      return std::nullopt;
    }
    bytes.append(chunk, static_cast<size_t>(n));
  }
}

}  // namespace nxtmap::sim
