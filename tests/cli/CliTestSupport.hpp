// Helpers for the console tests: running the built nxtmap binary and a private temp directory.
#pragma once
#include "tests/support/TempDir.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace nxtmap::cli::test {

inline std::string sourcePath(const std::string& relative) { return std::string(NXTMAP_SOURCE_DIR) + "/" + relative; }

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

inline std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

using ::nxtmap::test::TempDir;

struct RunOutput {
  int exitCode = -1;
  std::string out, err;
};

// Runs `nxtmap <args>` (args already shell-quoted as needed) from the repository root. With killAfterS > 0 the
// run is killed after that many seconds (coreutils timeout; the exit code is then 137).
inline RunOutput runCli(const std::string& args, int killAfterS = 0) {
  static int counter = 0;
  TempDir tmp("run" + std::to_string(counter++));
  const std::string outPath = tmp.path("out"), errPath = tmp.path("err");
  const std::string limit = killAfterS > 0 ? "timeout --signal=KILL " + std::to_string(killAfterS) + " " : "";
  const std::string cmd = "cd " + shellQuote(NXTMAP_SOURCE_DIR) + " && " + limit + shellQuote(NXTMAP_CLI_PATH) + " " +
                          args + " > " + shellQuote(outPath) + " 2> " + shellQuote(errPath) + " < /dev/null";
  const int status = std::system(cmd.c_str());
  RunOutput r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

}  // namespace nxtmap::cli::test
