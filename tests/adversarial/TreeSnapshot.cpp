#include "tests/adversarial/TreeSnapshot.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace nxtmap::adversarial {
namespace fs = std::filesystem;

TreeSnapshot TreeSnapshot::of(const std::string& root) {
  TreeSnapshot s;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& p = it->path();
    const std::string rel = fs::relative(p, root).string();
    const fs::file_status st = fs::symlink_status(p);
    if (fs::is_symlink(st)) {
      s.entries_[rel] = "l:" + fs::read_symlink(p).string();
    } else if (fs::is_directory(st)) {
      s.entries_[rel] = "d";
    } else if (fs::is_regular_file(st)) {
      std::ifstream in(p, std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      s.entries_[rel] = "f:" + bytes.str();
    } else {
      s.entries_[rel] = "other";
    }
  }
  return s;
}

std::string TreeSnapshot::differenceFrom(const TreeSnapshot& before) const {
  for (const auto& [path, what] : before.entries_) {
    const auto now = entries_.find(path);
    if (now == entries_.end()) return "removed: " + path;
    if (now->second != what) return "changed: " + path;
  }
  for (const auto& [path, what] : entries_) {
    if (before.entries_.count(path) == 0) return "added: " + path;
  }
  return "";
}

}  // namespace nxtmap::adversarial
