// GridFrame: a robot's grid laid on the plane. Cell (0, 0) is centred on `originCm`; the grid's "north"
// (towards smaller rows) points along compass `headingDeg`; cells are `cellCm` a side. The frame a
// robot starts in is its true start pose: a robot set down 10 degrees off square has a grid turned 10
// degrees against the walls, and the truth it is scored against is drawn on that grid.
#pragma once

#include "host/sim/Scene.hpp"

#include <cmath>

namespace nxtmap::sim {

struct GridFrame {
  Vec2 originCm{0.0, 0.0};  // plane point at the centre of cell (0, 0), cm
  double headingDeg = 0.0;  // compass direction of the grid's north, degrees
  double cellCm = 10.0;     // > 0

  // Plane point -> continuous grid coordinates (cells; cell (c, r) spans c - 0.5 .. c + 0.5).
  Vec2 toGrid(const Vec2& p) const {
    const double rad = headingDeg * 3.14159265358979323846 / 180.0;
    const Vec2 d = p - originCm;
    // The grid's +col axis is compass headingDeg + 90, +row axis headingDeg + 180.
    const double c = std::cos(rad), s = std::sin(rad);
    const double alongCol = d.x() * c + d.y() * s;   // component along (cos, sin) = compass h + 90
    const double alongRow = -d.x() * s + d.y() * c;  // along (-sin, cos) = compass h + 180
    return Vec2(alongCol / cellCm, alongRow / cellCm);
  }
  Vec2 toPlane(const Vec2& g) const {
    const double rad = headingDeg * 3.14159265358979323846 / 180.0;
    const double c = std::cos(rad), s = std::sin(rad);
    const double a = g.x() * cellCm, b = g.y() * cellCm;
    return originCm + Vec2(a * c - b * s, a * s + b * c);
  }
  // The cell holding plane point p.
  void cellOf(const Vec2& p, int& col, int& row) const {
    const Vec2 g = toGrid(p);
    col = static_cast<int>(std::floor(g.x() + 0.5));
    row = static_cast<int>(std::floor(g.y() + 0.5));
  }
};

}  // namespace nxtmap::sim
