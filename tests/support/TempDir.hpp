#pragma once
// Test helper shared by the test folders: a private temporary directory, removed with everything
// in it when the object goes away. (tests/support/ has no .cpp, so it builds no executable.)
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace nxtmap::test {

class TempDir {
 public:
  explicit TempDir(const std::string& tag = "t")
      : dir_(std::filesystem::temp_directory_path() / ("nxtmap_test_" + std::to_string(::getpid()) + "_" + tag)) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  // Path of `name` inside the directory (the directory itself for "").
  std::string path(const std::string& name = "") const { return name.empty() ? dir_.string() : (dir_ / name).string(); }
  // Writes `content` to `name` (creating sub-folders) and returns its path.
  std::string write(const std::string& name, const std::string& content) const {
    const auto p = dir_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace nxtmap::test
