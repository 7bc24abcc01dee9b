#pragma once
// Test helper: a write error on demand. While a FileSizeLimit lives, this process may not grow a file
// beyond `bytes` (RLIMIT_FSIZE): a write past it fails with EFBIG ("File too large") instead of raising
// SIGXFSZ, which is ignored meanwhile. Both are restored when the object goes away.
#include <sys/resource.h>

#include <csignal>

namespace nxtmap::test {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, oldHandler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*oldHandler_)(int) = SIG_DFL;
};

}  // namespace nxtmap::test
