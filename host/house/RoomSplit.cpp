#include "host/house/RoomSplit.hpp"

#include <algorithm>

namespace nxtmap::house {
namespace {

// Slice boundaries: parts + 1 lines from lo to hi (inclusive walls), the cut lines in between.
std::vector<int> slices(int lo, int hi, int parts) {
  std::vector<int> b;
  for (int i = 0; i <= parts; ++i) b.push_back(lo + (hi - lo) * i / parts);
  return b;
}

network::RoomMap crop(const network::RoomMap& m, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, m.minX());
  y0 = std::max(y0, m.minY());
  x1 = std::min(x1, m.maxX());
  y1 = std::min(y1, m.maxY());
  network::RoomMap out(x0, y0, std::max(0, x1 - x0 + 1), std::max(0, y1 - y0 + 1));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      out.set(c, m.at(c));
    }
  }
  return out;
}

}  // namespace

int RoomParts::partOf(Cell c) const {
  for (size_t i = 0; i < maps.size(); ++i) {
    if (maps[i].inside(c)) return static_cast<int>(i);
  }
  return -1;
}

RoomParts splitRoom(const network::RoomMap& map, const RoomInterpretation& r) {
  RoomParts out;
  const int px = r.valid ? std::max<int>(1, r.partsX) : 1, py = r.valid ? std::max<int>(1, r.partsY) : 1;
  if (px == 1 && py == 1) {
    out.maps.push_back(map);
    return out;
  }
  // Cut lines through the interior; the outer parts reach to the map's edges.
  std::vector<int> xs = slices(r.wallLine[3], r.wallLine[1], px), ys = slices(r.wallLine[2], r.wallLine[0], py);
  xs.front() = map.minX();
  xs.back() = map.maxX();
  ys.front() = map.minY();
  ys.back() = map.maxY();
  for (int j = 0; j < py; ++j) {
    for (int i = 0; i < px; ++i) out.maps.push_back(crop(map, xs[i], ys[j], xs[i + 1], ys[j + 1]));
  }
  // Gateways: runs of free cells on each cut line between two neighbouring parts.
  const auto addRuns = [&](int a, int b, bool vertical, int line, int from, int to) {
    std::vector<Cell> run;
    for (int k = from; k <= to + 1; ++k) {
      const Cell c = vertical ? Cell{static_cast<int16_t>(line), static_cast<int16_t>(k)}
                              : Cell{static_cast<int16_t>(k), static_cast<int16_t>(line)};
      if (k <= to && map.isFree(c)) {
        run.push_back(c);
        continue;
      }
      if (!run.empty()) out.cuts.push_back(RoomParts::Cut{a, b, run});
      run.clear();
    }
  };
  for (int j = 0; j < py; ++j) {
    for (int i = 0; i < px; ++i) {
      const int p = j * px + i;
      if (i + 1 < px) addRuns(p, p + 1, true, xs[i + 1], ys[j] + 1, ys[j + 1] - 1);
      if (j + 1 < py) addRuns(p, p + px, false, ys[j + 1], xs[i] + 1, xs[i + 1] - 1);
    }
  }
  return out;
}

}  // namespace nxtmap::house
