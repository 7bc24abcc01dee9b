// Helpers for the console tests: running the built nxtmap binary and a private temp directory.
#pragma once

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

// A private temporary directory, removed with everything in it when the object goes away.
class TempDir {
 public:
  explicit TempDir(const std::string& tag = "t")
      : dir_(std::filesystem::temp_directory_path() /
             ("nxtmap_cli_" + std::to_string(::getpid()) + "_" + tag)) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string path(const std::string& name = "") const { return name.empty() ? dir_.string() : (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    const auto p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

 private:
  std::filesystem::path dir_;
};

struct RunOutput {
  int exitCode = -1;
  std::string out, err;
};

// Runs `nxtmap <args>` (args already shell-quoted as needed) from the repository root.
inline RunOutput runCli(const std::string& args) {
  static int counter = 0;
  TempDir tmp("run" + std::to_string(counter++));
  const std::string outPath = tmp.path("out"), errPath = tmp.path("err");
  const std::string cmd = "cd " + shellQuote(NXTMAP_SOURCE_DIR) + " && " + shellQuote(NXTMAP_CLI_PATH) + " " + args +
                          " > " + shellQuote(outPath) + " 2> " + shellQuote(errPath) + " < /dev/null";
  const int status = std::system(cmd.c_str());
  RunOutput r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(outPath);
  r.err = readFile(errPath);
  return r;
}

}  // namespace nxtmap::cli::test
