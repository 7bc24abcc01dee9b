// GridLocaliser's measurement update (see GridLocaliser.hpp): a reading against the map, O(bins) per reading.
#include "common/check/Check.hpp"
#include "common/motion/GridLocaliser.hpp"

namespace nxtmap {
namespace {

constexpr int kSide = GridLocaliser::kSide;
constexpr int kRadius = GridLocaliser::kRadius;

constexpr int32_t floorDiv(int32_t a, int32_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
constexpr uint8_t saturate(int32_t v) { return static_cast<uint8_t>(v > 255 ? 255 : (v < 0 ? 0 : v)); }

// The first wall ahead, by (row across the beam, start cell along it): cells are counted from the believed cell
// along the sensor's axis (j) and to its right (row); cellMm >= 2 binMm and mountMm < cellMm bound both.
constexpr int kMaxRows = GridLocaliser::kRadius + 1;    // rows -5..5 with 2 bins a cell
constexpr int kMaxStarts = GridLocaliser::kRadius + 2;  // start cells -5..6
constexpr int16_t kUnknownBase = -20000;  // kUnknownBase + j: the first unknown cell, j, comes before any wall
constexpr int16_t kNoWall = 32767;                      // free cells as far as the beam reaches

// The cost of the reading for each true range, computed when first asked for: a reading meets a few dozen.
class CostCache {
 public:
  CostCache(const BeamModel& model, int16_t readingCm)
      : model_(model), readingCm_(readingCm), best_(model.bestCost(readingCm)) {}
  // The reading's cost given trueCm (BeamModel::kNothing: nothing in reach) less its best possible cost.
  uint8_t relative(int16_t trueCm) {
    const int slot = trueCm < 0 ? GridLocaliser::kMaxReachCm + 1 : trueCm;
    const uint8_t bit = static_cast<uint8_t>(1u << (slot % 8));
    if ((known_[slot / 8] & bit) == 0) {
      cost_[slot] = saturate(model_.cost(readingCm_, trueCm) - best_);
      known_[slot / 8] = static_cast<uint8_t>(known_[slot / 8] | bit);
    }
    return cost_[slot];
  }

 private:
  static constexpr int kSlots = GridLocaliser::kMaxReachCm + 2;
  const BeamModel& model_;
  int16_t readingCm_;
  uint8_t best_;
  uint8_t cost_[kSlots];
  uint8_t known_[(kSlots + 7) / 8] = {};
};

// Four unsigned bytes added lane by lane, each saturating at 255 (no carry crosses a lane).
constexpr uint32_t saturatingAdd(uint32_t a, uint32_t b) {
  constexpr uint32_t kHigh = 0x80808080u, kLow = 0x7F7F7F7Fu;
  const uint32_t low = (a & kLow) + (b & kLow);                // the low 7 bits of each lane, carry into bit 7
  const uint32_t sum = low ^ ((a ^ b) & kHigh);                // the lane sums modulo 256
  const uint32_t carry = ((a & b) | (low & (a | b))) & kHigh;  // lanes that overflowed
  const uint32_t ones = carry >> 7;
  return sum | ((ones << 8) - ones);  // overflowed lanes: 255
}
static_assert(saturatingAdd(0x01FF80F0u, 0x01017F20u) == 0x02FFFFFFu, "lane by lane, saturating");

// The beam's frame in cells: j along the sensor's axis from the believed cell, rows to its right.
struct BeamFrame {
  Dir axis, right;
  int32_t cell, half, reachMm;
  int32_t jLow, jHigh;  // the cells the window's sensor faces lie in, along the axis
  int32_t rows;         // ... and across it: -rows..rows
};

BeamFrame frameFor(const GridLocaliserParams& p, Dir axis, int32_t reachMm) {
  const int32_t cell = p.cellMm, half = cell / 2, extent = GridLocaliser::kRadius * p.binMm;
  const BeamFrame f{axis,
                    rotate(axis, 1),
                    cell,
                    half,
                    reachMm,
                    floorDiv(-extent + p.mountMm + half, cell),
                    floorDiv(extent + p.mountMm + half, cell),
                    (extent + half) / cell};
  NXTMAP_CHECK(2 * f.rows + 1 <= kMaxRows && f.jHigh - f.jLow + 1 <= kMaxStarts);
  return f;
}

// The first wall ahead of each start cell in each row: one walk per row, from beyond the beam's reach back.
void findWalls(const RoomGrid& map, Cell believed, const BeamFrame& f, int16_t (*wall)[kMaxStarts]) {
  const int32_t horizon = f.jHigh + (f.reachMm + f.cell - 1) / f.cell + 1;
  const int ax = dx(f.axis), ay = dy(f.axis), rx = dx(f.right), ry = dy(f.right);
  for (int32_t row = -f.rows; row <= f.rows; ++row) {
    int16_t ahead = kNoWall;
    for (int32_t j = horizon; j >= f.jLow; --j) {
      const CellState state = map.at(offset(believed, ax * j + rx * row, ay * j + ry * row));
      if (state == CellState::Occupied) ahead = static_cast<int16_t>(j);
      if (state == CellState::Unknown) ahead = static_cast<int16_t>(kUnknownBase + j);
      if (j <= f.jHigh) wall[row + f.rows][j - f.jLow] = ahead;
    }
  }
}

// The row costs laid out over the window's positions (see readingCosts); uninformed entries already 0.
void spreadOverWindow(const uint8_t (*rowCost)[kSide], const int8_t* row, bool alongX, uint8_t* add) {
  for (int iy = 0; iy < kSide; ++iy) {
    uint8_t* out = add + iy * kSide;
    if (alongX) {
      const uint8_t* in = rowCost[row[iy]];
      for (int ix = 0; ix < kSide; ++ix) out[ix] = in[ix];
    } else {
      for (int ix = 0; ix < kSide; ++ix) out[ix] = rowCost[row[ix]][iy];
    }
  }
}

// The reading's cost for each position of the window (a layer, [y * kSide + x]) into `add`, less the least of them;
// returns how many positions it weighed (all).
int readingCosts(const RoomGrid& map, Cell believed, const BeamFrame& f, const GridLocaliserParams& p,
                 const BeamModel& model, int16_t readingCm, uint8_t* add) {
  int16_t wall[kMaxRows][kMaxStarts];
  findWalls(map, believed, f, wall);
  // The window's bins by index: where each puts the sensor's face along the axis (u) and across it (v).
  const int32_t uSign = dx(f.axis) + dy(f.axis), vSign = dx(f.right) + dy(f.right);
  int32_t uMm[kSide];
  int8_t start[kSide], row[kSide];
  for (int i = 0; i < kSide; ++i) {
    uMm[i] = uSign * (i - kRadius) * p.binMm + p.mountMm;
    start[i] = static_cast<int8_t>(floorDiv(uMm[i] + f.half, f.cell) - f.jLow);
    row[i] = static_cast<int8_t>(floorDiv(vSign * (i - kRadius) * p.binMm + f.half, f.cell) + f.rows);
  }
  // The reading's cost for each (row, index along): the bins of a row share its walls.
  CostCache costs(model, readingCm);
  uint8_t rowCost[kMaxRows][kSide];
  uint8_t least = 255;
  for (int r = 0; r <= 2 * f.rows; ++r) {
    for (int i = 0; i < kSide; ++i) {
      const int16_t w = wall[r][start[i]];
      const bool unknown = w < kUnknownBase + 1000;
      int16_t trueCm = BeamModel::kNothing;
      if (w != kNoWall) {
        // To the near face of the wall cell, or of the first unknown cell; < 0: the face is in that cell.
        const int32_t mm = (unknown ? w - kUnknownBase : w) * f.cell - f.half - uMm[i];
        if (mm < f.reachMm) trueCm = static_cast<int16_t>(mm < 0 ? 0 : (mm + 5) / 10);
      }
      // Beyond an unknown cell the wall may be anywhere, or nowhere in reach: the reading's best explanation that
      // the known free cells before it allow (an echo from inside them is what tells).
      if (unknown && trueCm != BeamModel::kNothing) {
        if (readingCm == BeamModel::kNoEcho) trueCm = BeamModel::kNothing;
        else if (readingCm > trueCm) trueCm = readingCm;
      }
      rowCost[r][i] = costs.relative(trueCm);
      least = rowCost[r][i] < least ? rowCost[r][i] : least;
    }
  }
  for (int r = 0; r <= 2 * f.rows; ++r) {
    for (uint8_t& c : rowCost[r]) c = static_cast<uint8_t>(c - least);
  }
  spreadOverWindow(rowCost, row, !isVertical(f.axis), add);
  return kSide * kSide;
}

}  // namespace

int GridLocaliser::measure(const RoomGrid& map, Cell believed, Dir facing, Sensor s, int16_t readingCm) {
  const BeamFrame f = frameFor(params_, sensorDir(facing, s), model_.params().limitCm * 10);
  uint32_t addWords[kLayerWords] = {};
  const int weighed = readingCosts(map, believed, f, params_, model_, readingCm, reinterpret_cast<uint8_t*>(addWords));
  for (int i = 0; i < kLayerWords; ++i) readings_[i] = saturatingAdd(readings_[i], addWords[i]);
  if (cost(watchHeading_, watchIndex_) > kSlack) normalise();
  return weighed;
}

void GridLocaliser::fold() {
  for (auto& words : words_) {
    for (int i = 0; i < kLayerWords; ++i) words[i] = saturatingAdd(words[i], readings_[i]);
  }
  for (uint32_t& w : readings_) w = 0;
}

}  // namespace nxtmap
