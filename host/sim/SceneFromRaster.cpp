#include "host/sim/SceneFromRaster.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace nxtmap::sim {

namespace {

// A corner of the cell lattice: (col, row) of the cell whose top-left corner it is; 0..width, 0..height.
struct Corner {
  int x = 0, y = 0;
  bool operator==(const Corner& o) const { return x == o.x && y == o.y; }
};

// One maximal run of collinear boundary faces, directed with the free cells on its left.
struct Side {
  Corner from, to;
};

// Horizontal runs along lattice line y = row (between rows row - 1 and row), then vertical runs along
// x = col. A run continues while the faces keep the same orientation.
std::vector<Side> boundaryRuns(const World& w) {
  std::vector<Side> sides;
  for (int row = 0; row <= w.height(); ++row) {
    int runStart = 0, runKind = 0;  // kind: +1 free below (walk west), -1 free above (walk east), 0 none
    for (int col = 0; col <= w.width(); ++col) {
      int kind = 0;
      if (col < w.width()) {
        const bool above = w.blocked(col, row - 1), below = w.blocked(col, row);
        kind = above == below ? 0 : (below ? -1 : 1);
      }
      if (kind == runKind) continue;
      if (runKind == 1) sides.push_back(Side{{col, row}, {runStart, row}});
      if (runKind == -1) sides.push_back(Side{{runStart, row}, {col, row}});
      runStart = col;
      runKind = kind;
    }
  }
  for (int col = 0; col <= w.width(); ++col) {
    int runStart = 0, runKind = 0;  // kind: +1 free right (walk south), -1 free left (walk north), 0 none
    for (int row = 0; row <= w.height(); ++row) {
      int kind = 0;
      if (row < w.height()) {
        const bool left = w.blocked(col - 1, row), right = w.blocked(col, row);
        kind = left == right ? 0 : (right ? -1 : 1);
      }
      if (kind == runKind) continue;
      if (runKind == 1) sides.push_back(Side{{col, runStart}, {col, row}});
      if (runKind == -1) sides.push_back(Side{{col, row}, {col, runStart}});
      runStart = row;
      runKind = kind;
    }
  }
  return sides;
}

// Links the runs into closed rings of lattice corners: every corner has as many runs arriving as leaving,
// so a walk from any run returns to its start. Where two runs leave one corner (blocked cells meeting at
// a corner) the first unused is taken: either choice gives rings that touch without crossing.
std::vector<std::vector<Corner>> linkRings(const World& w, const std::vector<Side>& sides) {
  const auto key = [&](const Corner& c) {
    return static_cast<int64_t>(c.y) * (static_cast<int64_t>(w.width()) + 1) + c.x;
  };
  std::vector<std::pair<int64_t, size_t>> leaving;  // (corner key, side), sorted by corner
  leaving.reserve(sides.size());
  for (size_t i = 0; i < sides.size(); ++i) leaving.emplace_back(key(sides[i].from), i);
  std::sort(leaving.begin(), leaving.end());
  std::vector<char> used(sides.size(), 0);
  std::vector<std::vector<Corner>> rings;
  for (size_t first = 0; first < sides.size(); ++first) {
    if (used[first]) continue;
    std::vector<Corner> ring;
    size_t cur = first;
    while (true) {
      used[cur] = 1;
      ring.push_back(sides[cur].from);
      if (sides[cur].to == sides[first].from) break;
      // The walk can only end at its start, so an unused run leaves this corner.
      const int64_t at = key(sides[cur].to);
      auto it = std::lower_bound(leaving.begin(), leaving.end(), std::make_pair(at, size_t{0}));
      while (it != leaving.end() && it->first == at && used[it->second]) ++it;
      if (it == leaving.end() || it->first != at) break;
      cur = it->second;
    }
    rings.push_back(std::move(ring));
  }
  return rings;
}

}  // namespace

Scene traceRaster(const World& world) {
  const double cellCm = world.resolutionM() * 100.0;
  Scene scene;
  for (const std::vector<Corner>& corners : linkRings(world, boundaryRuns(world))) {
    Ring ring;
    ring.surface = Surface::Hard;
    ring.points.reserve(corners.size());
    for (const Corner& c : corners) ring.points.emplace_back(c.x * cellCm, c.y * cellCm);
    scene.addRing(std::move(ring));
  }
  scene.finish();
  return scene;
}

}  // namespace nxtmap::sim
