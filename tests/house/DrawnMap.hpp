// Small room maps drawn as text for the house table tests: rows top (highest y) first, the
// lower-left character is cell (x0, y0); characters in `walls` are occupied, in `frees` free, any
// other character unknown.
#pragma once

#include <cstring>
#include <string>
#include <vector>

#include "host/network/RoomMap.hpp"

namespace nxtmap::house::test {

inline network::RoomMap drawMap(const std::vector<std::string>& rows, int x0 = 0, int y0 = 0, const char* walls = "#",
                                const char* frees = ".") {
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows[0].size());
  network::RoomMap m(x0, y0, w, h);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const char ch = rows[static_cast<size_t>(r)][static_cast<size_t>(c)];
      const Cell cell{static_cast<int16_t>(x0 + c), static_cast<int16_t>(y0 + h - 1 - r)};
      if (std::strchr(walls, ch) != nullptr) m.set(cell, CellState::Occupied);
      if (std::strchr(frees, ch) != nullptr) m.set(cell, CellState::Free);
    }
  }
  return m;
}

// The cell of the first of `marks` found in the drawing (0, 0 when none), same frame as drawMap.
inline Cell markedCell(const std::vector<std::string>& rows, const char* marks, int x0 = 0, int y0 = 0) {
  const int h = static_cast<int>(rows.size());
  for (int r = 0; r < h; ++r) {
    const std::string& row = rows[static_cast<size_t>(r)];
    const size_t c = row.find_first_of(marks);
    if (c != std::string::npos)
      return Cell{static_cast<int16_t>(x0 + static_cast<int>(c)), static_cast<int16_t>(y0 + h - 1 - r)};
  }
  return Cell{};
}

// A drawn room and its one marked cell (the robot, the start...): drawMap plus markedCell.
struct DrawnRoom {
  network::RoomMap map;
  Cell mark{};
};
inline DrawnRoom drawRoom(const std::vector<std::string>& rows, const char* walls, const char* frees,
                          const char* marks) {
  return DrawnRoom{drawMap(rows, 0, 0, walls, frees), markedCell(rows, marks)};
}

}  // namespace nxtmap::house::test
