// Fixture files for the adversarial tables: small good worlds and houses, and the ways to spoil them.
#pragma once
#include <unistd.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>

#include "tests/adversarial/AdversarialCase.hpp"

namespace nxtmap::adversarial {

// A Moving AI world of the repository that maps in well under a second (start 1,20).
inline const char* kGoodMap = "{src}/worlds/seed-appendix-a/occupancy-120.map";
// A good saved house (three rooms, from `nxtmap sim-house worlds/houses/three-rooms.map --start 8,8 --save`).
inline const char* kHouseFixture = "tests/adversarial/data/house";

// An 8 x 6 ROS map_server world (walls round a free room) as dir/name.yaml + dir/name.pgm; `yamlBody` replaces
// the YAML's text when given ("{image}" in it stands for the PGM's file name).
inline void writeRosMap(const CaseDirs& d, const std::string& name, const std::string& yamlBody = "") {
  std::string pgm = "P5\n8 6\n255\n";
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 8; ++c) pgm += static_cast<char>((r == 0 || r == 5 || c == 0 || c == 7) ? 0 : 254);
  }
  d.write(name + ".pgm", pgm);
  std::string yaml = yamlBody.empty() ? "image: {image}\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                        "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
                                      : yamlBody;
  for (size_t at = yaml.find("{image}"); at != std::string::npos; at = yaml.find("{image}"))
    yaml.replace(at, 7, name + ".pgm");
  d.write(name + ".yaml", yaml);
}

// A ROS world whose YAML has `line` in place of the line starting with the same key.
inline std::function<void(const CaseDirs&)> rosWith(const std::string& line) {
  return [line](const CaseDirs& d) {
    std::string yaml =
        "image: {image}\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n";
    const std::string key = line.substr(0, line.find(':') + 1);
    const size_t at = yaml.find(key);
    yaml.replace(at, yaml.find('\n', at) - at, line);
    writeRosMap(d, "w", yaml);
  };
}

// dir/name as a symbolic link to `target` (e.g. /dev/zero behind a .map name).
inline void symlinkTo(const CaseDirs& d, const std::string& target, const std::string& name) {
  d.write(name + ".tmp", "");
  ::unlink(d.path(name + ".tmp").c_str());
  if (::symlink(target.c_str(), d.path(name).c_str()) != 0) throw std::runtime_error("symlink " + name);
}

// A copy of the good house in dir/house, with `from` replaced by `to` in its file `file` (when given).
inline std::function<void(const CaseDirs&)> houseWith(const std::string& file = "", const std::string& from = "",
                                                      const std::string& to = "") {
  return [=](const CaseDirs& d) {
    d.copy(kHouseFixture, "house");
    if (file.empty()) return;
    std::ifstream in(d.path("house/" + file), std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("fixture: '" + from + "' not in " + file);
    text.replace(at, from.size(), to);
    d.write("house/" + file, text);
  };
}

}  // namespace nxtmap::adversarial
