// Helpers for the planner tests: maps drawn as rows of text.
#pragma once
#include <string>
#include <vector>

#include "host/mapio/OccupancyMap.hpp"

namespace nxtmap::plan::test {

// '.' free, '#' or '@' occupied, '?' unknown; all rows the same width.
inline mapio::OccupancyMap mapFromRows(const std::vector<std::string>& rows) {
  mapio::OccupancyMap m(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), mapio::Occupancy::Free);
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) {
      const char ch = rows[r][c];
      m.set(static_cast<int>(c), static_cast<int>(r),
            ch == '.'   ? mapio::Occupancy::Free
            : ch == '?' ? mapio::Occupancy::Unknown
                        : mapio::Occupancy::Occupied);
    }
  }
  return m;
}

}  // namespace nxtmap::plan::test
