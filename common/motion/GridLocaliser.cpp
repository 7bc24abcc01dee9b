#include "common/motion/GridLocaliser.hpp"

#include "common/check/Check.hpp"
#include "common/math/IntAbs.hpp"
#include "common/math/IntRound.hpp"
#include "common/math/IntSqrt.hpp"

namespace nxtmap {
namespace {

constexpr int32_t floorDiv(int32_t a, int32_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
// Nearest integer to a / b (b > 0), halves away from zero.
constexpr uint8_t saturate(int32_t v) { return static_cast<uint8_t>(v > 255 ? 255 : (v < 0 ? 0 : v)); }

// Min-convolution of n costs `stride` apart with the kernel (c2, c1, 0, c1, c2): the log-domain blur.
void minConvolve(uint8_t* first, int stride, int n, uint8_t c1, uint8_t c2) {
  uint8_t out[GridLocaliser::kSide];
  for (int i = 0; i < n; ++i) {
    int32_t best = first[i * stride];
    for (int k = 1; k <= 2; ++k) {
      const int32_t tap = k == 1 ? c1 : c2;
      if (i - k >= 0 && first[(i - k) * stride] + tap < best) best = first[(i - k) * stride] + tap;
      if (i + k < n && first[(i + k) * stride] + tap < best) best = first[(i + k) * stride] + tap;
    }
    out[i] = static_cast<uint8_t>(best);
  }
  for (int i = 0; i < n; ++i) first[i * stride] = out[i];
}

}  // namespace

GridLocaliser::GridLocaliser(const GridLocaliserParams& params, const BeamParams& beam)
    : params_(params), model_(beam) {
  NXTMAP_CHECK(params.binMm >= 1 && params.headingStepMrad >= 1 && params.cellMm % params.binMm == 0);
  NXTMAP_CHECK(params.cellMm >= 2 * params.binMm && params.mountMm >= 0 && params.mountMm < params.cellMm);
  NXTMAP_CHECK(beam.limitCm <= kMaxReachCm);
  reset();
}

void GridLocaliser::reset(int32_t sigmaMm, int32_t sigmaMrad) {
  const int64_t varMm = int64_t{sigmaMm} * sigmaMm, varMrad = int64_t{sigmaMrad} * sigmaMrad;
  // Gaussian: x^2 / (2 sigma^2) nats = 4 x^2 / sigma^2 eighth-nats per axis.
  auto quad = [](int64_t v, int64_t var) -> int64_t { return v == 0 ? 0 : (var == 0 ? kFar : 4 * v * v / var); };
  for (int h = 0; h < kHeadings; ++h) {
    const int64_t ch = quad(int64_t{h - kHeadingRadius} * params_.headingStepMrad, varMrad);
    for (int y = 0; y < kSide; ++y) {
      const int64_t cy = quad(binCentreMm(y), varMm);
      for (int x = 0; x < kSide; ++x) {
        const int64_t c = ch + cy + quad(binCentreMm(x), varMm);
        bin(h, y, x) = c > kFar ? kFar : static_cast<uint8_t>(c);
      }
    }
  }
  for (auto& carry : carryMm_) carry[0] = carry[1] = 0;
  carryMrad_ = 0;
  varianceMm2_[0] = varianceMm2_[1] = varianceMrad2_ = 0;
  for (uint32_t& w : readings_) w = 0;
  normalise();
}

void GridLocaliser::shiftLayer(int h, int sx, int sy) {
  if (sx == 0 && sy == 0) return;
  // new[y][x] = old[y - sy][x - sx], walking away from the source so it is read before it is overwritten.
  for (int k = 0; k < kSide; ++k) {
    const int y = sy > 0 ? kSide - 1 - k : k;
    for (int m = 0; m < kSide; ++m) {
      const int x = sx > 0 ? kSide - 1 - m : m;
      const int fy = y - sy, fx = x - sx;
      const bool inside = fy >= 0 && fy < kSide && fx >= 0 && fx < kSide;
      bin(h, y, x) = inside ? bin(h, fy, fx) : kFar;
    }
  }
}

void GridLocaliser::shiftHeadings(int sh) {
  if (sh == 0) return;
  for (int k = 0; k < kHeadings; ++k) {
    const int h = sh > 0 ? kHeadings - 1 - k : k, from = h - sh;
    const bool inside = from >= 0 && from < kHeadings;
    for (int y = 0; y < kSide; ++y) {
      for (int x = 0; x < kSide; ++x) bin(h, y, x) = inside ? bin(from, y, x) : kFar;
    }
    carryMm_[h][0] = inside ? carryMm_[from][0] : 0;
    carryMm_[h][1] = inside ? carryMm_[from][1] : 0;
  }
}

void GridLocaliser::spreadAlong(int axis) {
  int64_t& variance = axis < 2 ? varianceMm2_[axis] : varianceMrad2_;
  const int64_t unit = axis < 2 ? params_.binMm : params_.headingStepMrad;
  const int64_t unit2 = unit * unit;
  // Spread in passes of at most 2 bins^2 (a 5-tap kernel holds that), once a quarter bin^2 has gathered.
  while (4 * variance >= unit2) {
    const int64_t pass = variance < 2 * unit2 ? variance : 2 * unit2;
    const uint8_t c1 = saturate(static_cast<int32_t>(4 * unit2 / pass));
    const uint8_t c2 = saturate(static_cast<int32_t>(16 * unit2 / pass));
    if (axis == 2) {
      for (int y = 0; y < kSide; ++y) {
        for (int x = 0; x < kSide; ++x) minConvolve(&bin(0, y, x), kLayerWords * 4, kHeadings, c1, c2);
      }
      variance -= pass;
      continue;
    }
    for (int h = 0; h < kHeadings; ++h) {
      for (int i = 0; i < kSide; ++i) {
        if (axis == 0) minConvolve(&bin(h, i, 0), 1, kSide, c1, c2);      // row i
        if (axis == 1) minConvolve(&bin(h, 0, i), kSide, kSide, c1, c2);  // column i
      }
    }
    variance -= pass;
  }
}

void GridLocaliser::normalise() {
  fold();
  uint8_t lowest = kFar;
  for (int h = 0; h < kHeadings; ++h) {
    const uint8_t* bins = layer(h);
    for (int i = 0; i < kSide * kSide; ++i) {
      if (bins[i] >= lowest) continue;
      lowest = bins[i];
      watchHeading_ = h;
      watchIndex_ = i;
    }
  }
  lower(lowest);
}

void GridLocaliser::lower(uint8_t by) {
  if (by == 0) return;
  for (int h = 0; h < kHeadings; ++h) {
    uint8_t* bins = layer(h);
    for (int i = 0; i < kSide * kSide; ++i) bins[i] = static_cast<uint8_t>(bins[i] - by);
  }
}

void GridLocaliser::drove(int32_t mm, Dir heading) {
  fold();
  const Dir right = rotate(heading, 1);
  for (int h = 0; h < kHeadings; ++h) {
    const int32_t side = static_cast<int32_t>(divRound(mm * (h - kHeadingRadius) * params_.headingStepMrad, 1000));
    int32_t* carry = carryMm_[h];
    carry[0] += dx(heading) * mm + dx(right) * side;
    carry[1] += dy(heading) * mm + dy(right) * side;
    const int32_t sx = static_cast<int32_t>(divRound(carry[0], params_.binMm)),
                  sy = static_cast<int32_t>(divRound(carry[1], params_.binMm));
    carry[0] -= sx * params_.binMm;
    carry[1] -= sy * params_.binMm;
    shiftLayer(h, sx, sy);
  }
  const int64_t along = int64_t{params_.slipPerMille} * abs32(mm);  // 1/1000 mm
  varianceMm2_[isVertical(heading) ? 1 : 0] += along * along / 1000000;
  const int64_t turn = int64_t{params_.driveMradPerCell} * abs32(mm);  // mrad * cellMm
  varianceMrad2_ += turn * turn / (int64_t{params_.cellMm} * params_.cellMm);
  for (int axis = 0; axis < 3; ++axis) spreadAlong(axis);
  normalise();
}

void GridLocaliser::rotated(int32_t mrad, int quarters) {
  fold();
  carryMrad_ += mrad - quarters * kQuarterMrad;
  const int32_t sh = static_cast<int32_t>(divRound(carryMrad_, params_.headingStepMrad));
  carryMrad_ -= sh * params_.headingStepMrad;
  shiftHeadings(sh);
  int64_t sigma = int64_t{params_.turnMradPerQuarter} * abs32(mrad) / kQuarterMrad;
  if (4 * sigma < params_.turnMradPerQuarter) sigma = params_.turnMradPerQuarter / 4;
  varianceMrad2_ += sigma * sigma;
  spreadAlong(2);
  normalise();
}

void GridLocaliser::recentre(Dir d, int cells) {
  fold();
  const int32_t bins = cells * (params_.cellMm / params_.binMm);
  for (int h = 0; h < kHeadings; ++h) shiftLayer(h, -dx(d) * bins, -dy(d) * bins);
  normalise();
}

GridLocaliser::Peak GridLocaliser::peak() const {
  int bestCost = kFar + 1, bestDistance = 0;
  Peak p;
  for (int h = -kHeadingRadius; h <= kHeadingRadius; ++h) {
    for (int y = -kRadius; y <= kRadius; ++y) {
      for (int x = -kRadius; x <= kRadius; ++x) {
        const int c = at(x, y, h), distance = abs32(x) + abs32(y) + abs32(h);
        if (c > bestCost || (c == bestCost && distance >= bestDistance)) continue;
        bestCost = c;
        bestDistance = distance;
        p = Peak{x * params_.binMm, y * params_.binMm, h * params_.headingStepMrad};
      }
    }
  }
  return p;
}

GridLocaliser::Rebase GridLocaliser::rebase() const {
  const Peak p = peak();
  const int32_t half = params_.cellMm / 2;
  Rebase r;
  if ((p.xMm + half) % params_.cellMm == 0 || (p.yMm + half) % params_.cellMm == 0) return r;  // on a face
  const int32_t cx = floorDiv(p.xMm + half, params_.cellMm), cy = floorDiv(p.yMm + half, params_.cellMm);
  if (cx == 0 && cy == 0) return r;
  int believedBest = kFar;
  for (int h = -kHeadingRadius; h <= kHeadingRadius; ++h) {
    for (int y = -kRadius; y <= kRadius; ++y) {
      for (int x = -kRadius; x <= kRadius; ++x) {
        if (abs32(x * params_.binMm) > half || abs32(y * params_.binMm) > half) continue;
        if (at(x, y, h) < believedBest) believedBest = at(x, y, h);
      }
    }
  }
  const int peakCost = at(p.xMm / params_.binMm, p.yMm / params_.binMm, p.thetaMrad / params_.headingStepMrad);
  if (believedBest - peakCost < params_.rebaseMargin) return r;
  r.needed = true;
  r.dxCells = static_cast<int16_t>(cx);
  r.dyCells = static_cast<int16_t>(cy);
  return r;
}

int32_t GridLocaliser::spreadMm() const {
  int lowest = kFar;
  for (int h = 0; h < kHeadings; ++h) {
    for (int i = 0; i < kSide * kSide; ++i) lowest = cost(h, i) < lowest ? cost(h, i) : lowest;
  }
  int64_t w = 0, wx = 0, wy = 0, wr2 = 0;
  for (int h = 0; h < kHeadings; ++h) {
    for (int iy = 0; iy < kSide; ++iy) {
      for (int ix = 0; ix < kSide; ++ix) {
        const int64_t p = BeamModel::expQ24(cost(h, iy * kSide + ix) - lowest), x = binCentreMm(ix),
                      y = binCentreMm(iy);
        w += p;
        wx += p * x;
        wy += p * y;
        wr2 += p * (x * x + y * y);
      }
    }
  }
  const int64_t mx = wx / w, my = wy / w, var = wr2 / w - mx * mx - my * my;
  return static_cast<int32_t>(isqrt(static_cast<uint64_t>(var > 0 ? var : 0)));
}

}  // namespace nxtmap
