#include "host/fileio/LeftBehind.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>

namespace nxtmap::fileio {
namespace fs = std::filesystem;

pid_t writerPid(const std::string& entry, const std::string& name, const std::string& infix) {
  const std::string prefix = name + infix;
  if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return 0;
  long pid = 0;
  const char* first = entry.data() + prefix.size();
  const char* last = entry.data() + entry.size();
  const auto res = std::from_chars(first, last, pid);
  if (res.ec != std::errc() || (res.ptr != last && *res.ptr != '-') || pid <= 0 || pid > INT32_MAX) return 0;
  return static_cast<pid_t>(pid);
}

bool processAlive(pid_t pid) { return ::kill(pid, 0) == 0 || errno != ESRCH; }

void removeLeftBehind(const fs::path& target, const std::string& infix, bool includingOwn) {
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string name = target.filename().string();
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    const pid_t pid = writerPid(e.path().filename().string(), name, infix);
    if (pid != 0 && ((includingOwn && pid == ::getpid()) || !processAlive(pid))) {
      std::error_code ignored;
      fs::remove_all(e.path(), ignored);
    }
  }
}

}  // namespace nxtmap::fileio
