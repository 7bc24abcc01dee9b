#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// FaceLines: where, inside their cells, the faces of the walls the robot reads for its pose lie.
//
// A cell map says a wall is somewhere in a cell; in a real room its face may lie anywhere in it
// (RangeGeometry::faceMarginCm), so a pose reading that takes the face to be on the cell's edge is off by up to
// a cell, the same way every time that wall is read. Faces read along an axis share a line: looking north, every
// wall face in row y lies at the same height when the walls are straight and square to the map (rectilinear
// rooms, a squared start). One value per line and beam direction: the face's distance past the near edge of its
// cell (mm, in the beam's direction) with its variance, learnt from readings and the robot's offset as well as
// that was known, each weighed in by its variance. A reading that disagrees by more than kAgreeMm and 3 sigma is
// another face on the same line (a table leg before the wall) or a bad echo: not learnt. Lines are the cell
// coordinate modulo kLines (a wider grid shares lines between far-apart rows, kept apart by the same test).
// 1 KiB, owned by the pilot.
class FaceLines {
 public:
  static constexpr int kLines = 64;
  static constexpr int16_t kUnknown = -32768;
  static constexpr int32_t kAgreeMm = 30;        // a reading this far from a learnt face, and 3 sigma, is another face
  static constexpr int32_t kMaxVarMm2 = 65535;   // variances are kept to this (255 mm, 1 sigma)

  FaceLines() { clear(); }
  void clear();

  // The face of `wall`, seen along beam direction d: mm past the cell's near edge, and how well that is known
  // (variance, mm^2). False when not learnt.
  bool face(Cell wall, Dir d, int32_t& pastEdgeMm, int32_t& varianceMm2) const;
  // A reading put the face of `wall`, seen along d, pastEdgeMm past its near edge (|.| < 32768), to varianceMm2
  // (> 0): the first one is kept as it is, later ones are weighed in by their variances (a Kalman update).
  // Returns whether it was learnt (new, or agreeing with what was learnt).
  bool learn(Cell wall, Dir d, int32_t pastEdgeMm, int32_t varianceMm2);
  // Lines with a learnt face.
  int known() const;

 private:
  struct Face {
    int16_t mm = kUnknown;  // past the near edge
    uint16_t var = 0;       // mm^2
  };
  Face& slot(Cell wall, Dir d);
  const Face& slot(Cell wall, Dir d) const;

  Face faces_[4][kLines];  // by beam Dir, then line (row for North/South, column for East/West)
};
static_assert(sizeof(FaceLines) == 4 * FaceLines::kLines * 4, "FaceLines: 1 KiB on the brick");

}  // namespace nxtmap
