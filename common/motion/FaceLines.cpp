#include "common/motion/FaceLines.hpp"

namespace nxtmap {

void FaceLines::clear() {
  for (auto& byDir : faces_)
    for (Face& f : byDir) f = Face{};
}

FaceLines::Face& FaceLines::slot(Cell wall, Dir d) {
  const int16_t line = isVertical(d) ? wall.y : wall.x;
  return faces_[static_cast<int>(d)][static_cast<uint16_t>(line) % kLines];
}

const FaceLines::Face& FaceLines::slot(Cell wall, Dir d) const {
  const int16_t line = isVertical(d) ? wall.y : wall.x;
  return faces_[static_cast<int>(d)][static_cast<uint16_t>(line) % kLines];
}

bool FaceLines::face(Cell wall, Dir d, int32_t& pastEdgeMm, int32_t& varianceMm2) const {
  const Face& f = slot(wall, d);
  if (f.mm == kUnknown) return false;
  pastEdgeMm = f.mm;
  varianceMm2 = f.var;
  return true;
}

bool FaceLines::learn(Cell wall, Dir d, int32_t pastEdgeMm, int32_t varianceMm2) {
  if (pastEdgeMm <= kUnknown || pastEdgeMm > 32767 || varianceMm2 <= 0) return false;
  if (varianceMm2 > kMaxVarMm2) varianceMm2 = kMaxVarMm2;
  Face& f = slot(wall, d);
  if (f.mm == kUnknown) {
    f.mm = static_cast<int16_t>(pastEdgeMm);
    f.var = static_cast<uint16_t>(varianceMm2);
    return true;
  }
  const int64_t diff = pastEdgeMm - f.mm, spread = int64_t{f.var} + varianceMm2;
  if ((diff > kAgreeMm || diff < -kAgreeMm) && diff * diff > 9 * spread) return false;
  // Weighed by the variances: the gain is f.var / spread.
  const int64_t step = diff * f.var;
  f.mm = static_cast<int16_t>(f.mm + (step >= 0 ? (step + spread / 2) / spread : -((-step + spread / 2) / spread)));
  const int64_t var = int64_t{f.var} * varianceMm2 / spread;
  f.var = static_cast<uint16_t>(var < 1 ? 1 : var);
  return true;
}

int FaceLines::known() const {
  int n = 0;
  for (const auto& byDir : faces_)
    for (const Face& f : byDir) n += f.mm != kUnknown ? 1 : 0;
  return n;
}

}  // namespace nxtmap
