// Helpers shared by the simulator tests: fixture paths and throw-away files.
#pragma once
#include "tests/support/TempDir.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace nxtmap::sim::test {

inline std::string dataPath(const std::string& name) {
  return std::string(NXTMAP_SOURCE_DIR) + "/tests/sim/data/" + name;
}

using ::nxtmap::test::TempDir;

}  // namespace nxtmap::sim::test
