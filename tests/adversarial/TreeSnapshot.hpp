// TreeSnapshot: every entry under a directory (kind, and the bytes of each file), so a test can show that a
// refused command changed nothing: no file written, replaced, truncated or deleted, no folder left behind.
#pragma once
#include <map>
#include <string>

namespace nxtmap::adversarial {

class TreeSnapshot {
 public:
  // Reads everything under `root` (symbolic links are recorded, not followed).
  static TreeSnapshot of(const std::string& root);

  // "" when the two trees are the same, else the first difference, e.g. "added: out/house.saving-123".
  std::string differenceFrom(const TreeSnapshot& before) const;

 private:
  std::map<std::string, std::string> entries_;  // relative path -> kind + content ("f:<bytes>", "d", "l:<target>")
};

}  // namespace nxtmap::adversarial
