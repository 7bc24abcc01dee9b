#include "host/plan/JumpTable.hpp"

namespace nxtmap::plan {

constexpr int JumpTable::kDirs[8][2];

int JumpTable::direction(int dc, int dr) {
  for (int d = 0; d < 8; ++d) {
    if (kDirs[d][0] == dc && kDirs[d][1] == dr) return d;
  }
  return -1;
}

JumpTable::JumpTable(const Traversability& grid) : gridId_(grid.id()), table_(grid.paddedSize() * 8, 0) {
  const int w = grid.width();
  const int h = grid.height();
  auto idx = [&](int c, int r) { return grid.index(MapCell{c, r}); };
  auto open = [&](int c, int r) { return grid.open(idx(c, r)); };  // c in -1..w, r in -1..h
  auto set = [&](int c, int r, int d, int v) {
    table_[static_cast<size_t>(idx(c, r)) * 8 + static_cast<size_t>(d)] = static_cast<int16_t>(v);
  };
  auto get = [&](int c, int r, int d) {
    return static_cast<int>(table_[static_cast<size_t>(idx(c, r)) * 8 + static_cast<size_t>(d)]);
  };
  // Extends the value of the next cell by one step.
  auto extend = [](int next) { return next > 0 ? next + 1 : next - 1; };

  // Straight directions: the value of a cell follows from the next cell along the direction.
  for (int d = 0; d < 4; ++d) {
    const int dc = kDirs[d][0], dr = kDirs[d][1];
    // A cell n reached moving (dc, dr) has a forced neighbour beside it when the cell beside its
    // predecessor is blocked.
    auto forced = [&](int c, int r) {
      if (dr == 0) return (open(c, r - 1) && !open(c - dc, r - 1)) || (open(c, r + 1) && !open(c - dc, r + 1));
      return (open(c - 1, r) && !open(c - 1, r - dr)) || (open(c + 1, r) && !open(c + 1, r - dr));
    };
    const int c0 = dc > 0 ? w - 1 : 0, c1 = dc > 0 ? -1 : w, cs = dc > 0 ? -1 : 1;
    const int r0 = dr > 0 ? h - 1 : 0, r1 = dr > 0 ? -1 : h, rs = dr > 0 ? -1 : 1;
    for (int r = r0; r != r1; r += rs) {
      for (int c = c0; c != c1; c += cs) {
        const int nc = c + dc, nr = r + dr;
        int v = 0;
        if (!open(nc, nr)) {
          v = 0;
        } else if (forced(nc, nr)) {
          v = 1;
        } else {
          v = extend(get(nc, nr, d));  // the next cell is inside the map, as it is open
        }
        set(c, r, d, v);
      }
    }
  }
  // Diagonal directions: stop where a straight jump along either component finds a jump point.
  for (int d = 4; d < 8; ++d) {
    const int dc = kDirs[d][0], dr = kDirs[d][1];
    const int dh = direction(dc, 0), dv = direction(0, dr);
    const int c0 = dc > 0 ? w - 1 : 0, c1 = dc > 0 ? -1 : w, cs = dc > 0 ? -1 : 1;
    const int r0 = dr > 0 ? h - 1 : 0, r1 = dr > 0 ? -1 : h, rs = dr > 0 ? -1 : 1;
    for (int r = r0; r != r1; r += rs) {
      for (int c = c0; c != c1; c += cs) {
        const int nc = c + dc, nr = r + dr;
        int v = 0;
        if (!open(nc, nr) || !open(nc, r) || !open(c, nr)) {
          v = 0;
        } else if (get(nc, nr, dh) > 0 || get(nc, nr, dv) > 0) {
          v = 1;
        } else {
          v = extend(get(nc, nr, d));
        }
        set(c, r, d, v);
      }
    }
  }
}

}  // namespace nxtmap::plan
