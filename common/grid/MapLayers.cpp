#include "common/grid/MapLayers.hpp"

namespace nxtmap {
namespace {
constexpr int kSureFree = -7;
constexpr int kSureOccupied = 7;
constexpr int kHitWeight = 1;  // an echo counts as much as a miss
constexpr int kMissWeight = 1;
// A blocked move into a surely free cell counts as this many echoes from it (MapLayers::observeBlocked).
constexpr int kBlockedWeight = 3;
}  // namespace

MapLayers::MapLayers(const Storage& storage, int16_t width, int16_t height)
    : grid_(storage.grid, width, height),
      evidence_(storage.evidence, width, height),
      reads_(storage.reads, width, height),
      diagonals_(storage.diagonals, width, height) {
  clear();
}

void MapLayers::clear() {
  grid_.clear();
  evidence_.fill(8);
  reads_.fill(0);
  diagonals_.fill(0);
}

bool MapLayers::setEvidence(Cell c, int e) {
  if (e < kSureFree) e = kSureFree;
  if (e > kSureOccupied) e = kSureOccupied;
  if (!grid_.set(c, e > 0 ? CellState::Occupied : CellState::Free)) return false;
  evidence_.set(c, static_cast<uint8_t>(e + 8));
  return true;
}

bool MapLayers::observeFree(Cell c) {
  const int e = grid_.isUnknown(c) ? 0 : evidence(c);
  return setEvidence(c, e - kMissWeight);
}

bool MapLayers::observeOccupied(Cell c) {
  const int e = grid_.isUnknown(c) ? 0 : evidence(c);
  return setEvidence(c, e + kHitWeight);
}

void MapLayers::forget(Cell c) {
  grid_.forget(c);
  evidence_.set(c, 8);
  reads_.set(c, 0);
  diagonals_.set(c, 0);
}

bool MapLayers::markVisited(Cell c) { return setEvidence(c, kSureFree); }
bool MapLayers::markBlocked(Cell c) { return setEvidence(c, kSureOccupied); }
bool MapLayers::observeBlocked(Cell c) {
  if (!grid_.isUnknown(c) && evidence(c) <= kSureFree) return setEvidence(c, kSureFree + kBlockedWeight);
  return markBlocked(c);
}

void MapLayers::diagonalSlot(Cell c, int sx, int sy, Cell& base, uint8_t& bit) {
  // Stored at the lower cell of the pair: bit 0 = towards (+1,+1), bit 1 = towards (-1,+1).
  base = sy > 0 ? c : offset(c, sx, sy);
  const int upDx = sy > 0 ? sx : -sx;
  bit = upDx > 0 ? 1u : 2u;
}

bool MapLayers::diagonalUsed(Cell c, int sx, int sy) const {
  Cell base;
  uint8_t bit;
  diagonalSlot(c, sx, sy, base, bit);
  return (diagonals_.at(base) & bit) != 0;
}

void MapLayers::setDiagonalUsed(Cell c, int sx, int sy) {
  Cell base;
  uint8_t bit;
  diagonalSlot(c, sx, sy, base, bit);
  diagonals_.set(base, static_cast<uint8_t>(diagonals_.at(base) | bit));
}

Cell MapLayers::restructure() {
  const Cell shift = grid_.restructure();
  evidence_.translate(shift.x, shift.y);
  reads_.translate(shift.x, shift.y);
  diagonals_.translate(shift.x, shift.y);
  return shift;
}

}  // namespace nxtmap
