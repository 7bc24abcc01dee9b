#include "host/plan/Traversability.hpp"

#include <algorithm>
#include <atomic>

namespace nxtmap::plan {
namespace {
uint64_t nextId() {
  static std::atomic<uint64_t> counter{0};
  return ++counter;
}
}  // namespace

Traversability::Traversability(const mapio::OccupancyMap& map, bool unknownTraversable, int clearanceCells)
    : id_(nextId()), width_(map.width()), height_(map.height()) {
  const int k = std::clamp(clearanceCells, 0, kMaxClearance);
  const size_t s = static_cast<size_t>(stride());
  cells_.assign(s * static_cast<size_t>(height_ + 2), 0);
  auto usable = [&](int c, int r) {
    const mapio::Occupancy o = map.at(c, r);
    return o == mapio::Occupancy::Free || (unknownTraversable && o == mapio::Occupancy::Unknown);
  };
  if (k == 0) {
    for (int r = 0; r < height_; ++r) {
      for (int c = 0; c < width_; ++c) cells_[index(MapCell{c, r})] = usable(c, r) ? 1 : 0;
    }
    bits_ = BitGrid(stride(), height_ + 2, cells_);
    return;
  }
  // Summed-area table of unusable cells: (W+1) x (H+1).
  const size_t w1 = static_cast<size_t>(width_) + 1;
  std::vector<int32_t> sum(w1 * (static_cast<size_t>(height_) + 1), 0);
  for (int r = 0; r < height_; ++r) {
    for (int c = 0; c < width_; ++c) {
      const size_t at = static_cast<size_t>(r + 1) * w1 + static_cast<size_t>(c + 1);
      sum[at] = (usable(c, r) ? 0 : 1) + sum[at - 1] + sum[at - w1] - sum[at - w1 - 1];
    }
  }
  for (int r = k; r < height_ - k; ++r) {
    for (int c = k; c < width_ - k; ++c) {
      const size_t r0 = static_cast<size_t>(r - k), r1 = static_cast<size_t>(r + k + 1);
      const size_t c0 = static_cast<size_t>(c - k), c1 = static_cast<size_t>(c + k + 1);
      const int32_t bad = sum[r1 * w1 + c1] - sum[r0 * w1 + c1] - sum[r1 * w1 + c0] + sum[r0 * w1 + c0];
      cells_[index(MapCell{c, r})] = bad == 0 ? 1 : 0;
    }
  }
  bits_ = BitGrid(stride(), height_ + 2, cells_);
}

bool Traversability::validPath(const std::vector<MapCell>& path, double& lengthOut) const {
  lengthOut = 0.0;
  if (path.empty()) return false;
  if (!passable(path.front())) return false;
  for (size_t i = 1; i < path.size(); ++i) {
    const int dc = path[i].col - path[i - 1].col;
    const int dr = path[i].row - path[i - 1].row;
    if (std::abs(dc) > 1 || std::abs(dr) > 1 || (dc == 0 && dr == 0)) return false;
    if (!canStep(path[i - 1], dc, dr)) return false;
    lengthOut += (dc != 0 && dr != 0) ? kSqrt2 : 1.0;
  }
  return true;
}

}  // namespace nxtmap::plan
