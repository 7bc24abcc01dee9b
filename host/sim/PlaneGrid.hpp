// PlaneGrid: a uniform grid of square cells laid over a box of the plane (cm, x right, y down); the
// Scene's bucket index and its finer cover are two of them.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace nxtmap::sim {

using Vec2 = Eigen::Vector2d;  // as in Scene.hpp

struct PlaneGrid {
  Vec2 origin{0.0, 0.0};   // plane point of cell (0, 0)'s smaller-x, smaller-y corner, cm
  double cellCm = 1.0;     // > 0
  double perCellCm = 1.0;  // 1 / cellCm
  int countX = 0, countY = 0;

  PlaneGrid() = default;
  PlaneGrid(const Vec2& corner, double side, int columns, int rows)
      : origin(corner), cellCm(side), perCellCm(1.0 / side), countX(columns), countY(rows) {}

  int cells() const { return countX * countY; }
  int index(int col, int row) const { return row * countX + col; }
  // The cell holding p (a point on a cell line may go to either side); false outside the grid.
  bool cellOf(const Vec2& p, int& col, int& row) const {
    const double cx = std::floor((p.x() - origin.x()) * perCellCm);
    const double cy = std::floor((p.y() - origin.y()) * perCellCm);
    if (!(cx >= 0.0 && cy >= 0.0 && cx < countX && cy < countY)) return false;
    col = static_cast<int>(cx);
    row = static_cast<int>(cy);
    return true;
  }
  int clampedCol(double x) const { return clampedCell(x - origin.x(), countX); }
  int clampedRow(double y) const { return clampedCell(y - origin.y(), countY); }

  // Calls visit(col, row) for every cell that segment ab comes within pad (cm) of, and perhaps a few
  // more (each row band's part of the segment is taken with its box).
  template <class Visit>
  void forCellsNearSegment(const Vec2& a, const Vec2& b, double pad, Visit visit) const {
    const int row0 = clampedRow(std::min(a.y(), b.y()) - pad), row1 = clampedRow(std::max(a.y(), b.y()) + pad);
    for (int row = row0; row <= row1; ++row) {
      const double lo = origin.y() + row * cellCm - pad, hi = lo + cellCm + 2.0 * pad;
      double s0 = 0.0, s1 = 1.0;
      if (a.y() != b.y()) {
        const double sa = (lo - a.y()) / (b.y() - a.y()), sb = (hi - a.y()) / (b.y() - a.y());
        s0 = std::max(0.0, std::min(sa, sb));
        s1 = std::min(1.0, std::max(sa, sb));
        if (s0 > s1) continue;
      }
      const double x0 = a.x() + s0 * (b.x() - a.x()), x1 = a.x() + s1 * (b.x() - a.x());
      const int col0 = clampedCol(std::min(x0, x1) - pad), col1 = clampedCol(std::max(x0, x1) + pad);
      for (int col = col0; col <= col1; ++col) visit(col, row);
    }
  }
  // Calls visit(col, row) for every cell meeting the box low..high (clamped to the grid).
  template <class Visit>
  void forCellsInBox(const Vec2& low, const Vec2& high, Visit visit) const {
    for (int row = clampedRow(low.y()); row <= clampedRow(high.y()); ++row) {
      for (int col = clampedCol(low.x()); col <= clampedCol(high.x()); ++col) visit(col, row);
    }
  }

 private:
  int clampedCell(double offset, int count) const {
    const double c = std::floor(offset * perCellCm);
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(count - 1)));
  }
};

}  // namespace nxtmap::sim
