#include "common/sensing/BeamInverse.hpp"

namespace nxtmap {
namespace {

// tan a and cos a in per mille for a in mrad (0..600), rounded: the first terms of their series (within 0.5 %).
constexpr int32_t tanPerMille(int64_t a) {
  return static_cast<int32_t>(a + (a * a * a + 1500000) / 3000000 +
                              (2 * a * a * a * a * a + 7500000000000) / 15000000000000);
}
constexpr int32_t cosPerMille(int64_t a) {
  return static_cast<int32_t>(1000 - (a * a + 1000) / 2000 + (a * a * a * a + 12000000000) / 24000000000);
}

struct Cone {
  const RangeGeometry& g;
  int32_t tan, cos;  // per mille
  int32_t nearCm(int k) const { return (2 * k - 1) * g.cellCm / 2 - g.mountCm; }
  int32_t farCm(int k) const { return (2 * k + 1) * g.cellCm / 2 - g.mountCm; }
  // The cone covers a quarter of the width of the cells beside cell k, from their near face on.
  bool coversBeside(int k) const { return 4 * nearCm(k) * tan >= 3 * g.cellCm * 1000; }
  // All of cell k (and the cone's part beside it) lies nearer than rangeCm.
  bool wholeBefore(int k, int32_t rangeCm) const { return farCm(k) * 1000 < rangeCm * cos; }
  // The arc at rangeCm is at least a cell wide.
  bool arcSpreads(int32_t rangeCm) const { return 2 * rangeCm * tan >= g.cellCm * 1000; }
};

class MarkWriter {
 public:
  MarkWriter(ConeMark* out, int capacity) : out_(out), capacity_(capacity) {}
  void add(int along, int side, int weight) {
    if (count_ < capacity_)
      out_[count_++] = ConeMark{static_cast<int8_t>(along), static_cast<int8_t>(side), static_cast<int8_t>(weight)};
  }
  int count() const { return count_; }

 private:
  ConeMark* out_;
  int capacity_;
  int count_ = 0;
};

// Free cells 1..lastAxis on the axis (axisWeight) and beside it where the cone covers them wholly before rangeCm.
void markFree(const Cone& cone, int lastAxis, int32_t rangeCm, int axisWeight, bool beside, MarkWriter& w) {
  for (int k = 1; k <= lastAxis; ++k) {
    w.add(k, 0, -axisWeight);
    if (beside && cone.coversBeside(k) && cone.wholeBefore(k, rangeCm)) {
      w.add(k, -1, -1);
      w.add(k, 1, -1);
    }
  }
}

}  // namespace

int inverseBeam(const RangeGeometry& geometry, int32_t coneHalfMrad, const RangeReading& reading, ConeMark* out,
                int capacity) {
  const int32_t a = coneHalfMrad < 0 ? 0 : (coneHalfMrad > 600 ? 600 : coneHalfMrad);
  const Cone cone{geometry, tanPerMille(a), cosPerMille(a)};
  MarkWriter w(out, capacity);
  switch (reading.status) {
    case RangeStatus::Good: {
      const int hit = geometry.hitCell(reading.cm);
      markFree(cone, hit - 1, reading.cm, 2, true, w);
      if (!cone.arcSpreads(reading.cm)) {
        w.add(hit, 0, 2);
      } else {
        w.add(hit, 0, 1);
        w.add(hit, -1, 1);
        w.add(hit, 1, 1);
      }
      break;
    }
    case RangeStatus::TooFar: markFree(cone, geometry.freeCells(), geometry.maxCm, 2, true, w); break;
    case RangeStatus::NoEcho: markFree(cone, geometry.freeCells(), geometry.maxCm, 1, false, w); break;
    case RangeStatus::TooNear: w.add(1, 0, 2); break;
    case RangeStatus::Inconsistent: break;
  }
  return w.count();
}

}  // namespace nxtmap
