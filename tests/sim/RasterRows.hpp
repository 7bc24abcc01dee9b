// A raster's cells as text rows ('#' blocked, '.' free) and the box rings drawn in, shared by the truth raster
// tests (TruthRasterTest, TracedRasterTest).
#pragma once

#include <string>
#include <vector>

#include "host/sim/TruthRaster.hpp"

namespace nxtmap::sim::test {

inline Ring box(double x0, double y0, double x1, double y1) {
  return Ring{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}};
}

inline std::vector<std::string> rowsOf(const World& w) {
  std::vector<std::string> rows;
  for (int r = 0; r < w.height(); ++r) {
    std::string line;
    for (int c = 0; c < w.width(); ++c) line += w.blocked(c, r) ? '#' : '.';
    rows.push_back(line);
  }
  return rows;
}

inline std::string joined(const std::vector<std::string>& rows) {
  std::string s;
  for (const std::string& r : rows) s += r + "\n";
  return s;
}

}  // namespace nxtmap::sim::test
