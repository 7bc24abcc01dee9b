#include "host/bench/BenchWorlds.hpp"

namespace nxtmap::bench {

std::filesystem::path worldsRoot() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(fs::path("worlds") / "seed-appendix-a", ec)) return "worlds";
  return fs::path(__FILE__).parent_path().parent_path().parent_path() / "worlds";
}

}  // namespace nxtmap::bench
