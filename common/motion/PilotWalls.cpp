// The pilot's readings of the walls: which wall a reading names (a cell the map holds, a face learnt), the side
// walls watched along a drive, when a reading for the pose is wanted, and a reading moved to the believed cell's
// centre for the explorer.
#include "common/math/IntAbs.hpp"
#include "common/math/IntSqrt.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {
namespace {
constexpr uint8_t bitOf(Dir d) { return static_cast<uint8_t>(1u << static_cast<int>(d)); }
}  // namespace

bool Pilot::firstWall(Dir d, Cell& wall, int16_t& k) const {
  const MapLayers& map = explorer_.map();
  const Cell at = explorer_.pose().cell;
  for (k = 1; k <= poseCells_; ++k) {
    wall = advance(at, d, k);
    const CellState st = map.at(wall);
    if (st != CellState::Free) return st == CellState::Occupied;
  }
  return false;
}

bool Pilot::knownWall(Dir d, int32_t& faceMm, Cell& c, int32_t* faceVarianceMm2) const {
  int16_t k = 0;
  if (!firstWall(d, c, k) || explorer_.map().evidence(c) < config_.minWallEvidence) return false;
  if (virtual_ != nullptr && virtual_->contains(c)) return false;
  faceMm = (2 * k - 1) * cellMm_ / 2 - static_cast<int32_t>(explorer_.config().geometry.mountCm) * 10;
#ifndef NXTMAP_NO_START_SQUARING
  const RangeGeometry& g = explorer_.config().geometry;
  if (g.facesAnywhere()) {  // faces anywhere: only a face learnt is a landmark
    int32_t pastEdgeMm = 0, var = 0;
    if (!faces_.face(c, d, pastEdgeMm, var)) return false;
    if (faceVarianceMm2 != nullptr) *faceVarianceMm2 = var;
    faceMm = (2 * k - 1) * cellMm_ / 2 + pastEdgeMm - static_cast<int32_t>(g.mountCm) * 10;
  }
#else
  (void)faceVarianceMm2;  // faces are taken where RangeGeometry::faceMm puts them, exactly
#endif
  return true;
}

void Pilot::learnFace(Dir d, const RangeReading& r) {
#ifdef NXTMAP_NO_START_SQUARING
  (void)d;
  (void)r;
#else
  const RangeGeometry& g = explorer_.config().geometry;
  const int64_t sure = static_cast<int64_t>(config_.learnFaceBelowMm) * config_.learnFaceBelowMm;
  const int64_t var = tracker_.varianceAlong(d) + tracker_.readingVariance();
  if (!g.facesAnywhere() || r.status != RangeStatus::Good || var > sure) return;
  const int32_t fromCentre = (r.cm + g.mountCm) * 10 + tracker_.along(d);
  const int32_t k = (2 * (fromCentre - g.echoMarginCm * 10) + cellMm_) / (2 * cellMm_);
  Cell wall{};
  int16_t first = 0;
  if (k < 1 || !firstWall(d, wall, first) || first != k) return;  // not the map's first wall along d
  if (virtual_ != nullptr && virtual_->contains(wall)) return;
  (void)faces_.learn(wall, d, fromCentre - (2 * k - 1) * cellMm_ / 2, static_cast<int32_t>(var));
#endif
}

bool Pilot::straightFace(Cell c, Dir d) const {
  const MapLayers& map = explorer_.map();
  for (int side = -1; side <= 1; side += 2) {
    const Cell beside = advance(c, rotate(d, side));
    if (map.at(beside) != CellState::Occupied || map.at(advance(beside, opposite(d))) != CellState::Free) return false;
  }
  return true;
}

int16_t Pilot::wallLine(Dir d, int32_t rangeMm) const {
  // The echo's cell along d: its face lies (k - 1/2) cells from the believed cell's centre.
  const RangeGeometry& g = explorer_.config().geometry;
  const int32_t fromCentre = rangeMm + (g.mountCm - (g.facesAnywhere() ? g.echoMarginCm : 0)) * 10 + tracker_.along(d);
  const int32_t k = (2 * fromCentre + cellMm_) / (2 * cellMm_);
  const Cell at = explorer_.pose().cell;
  const int32_t base = isVertical(d) ? at.y : at.x;
  const int32_t sign = isVertical(d) ? dy(d) : dx(d);
  return static_cast<int16_t>(base + sign * k);
}

void Pilot::observeSide(Dir d, int32_t rangeMm) {
  SideSlope slope;
  if (!sides_.pair(d, wallLine(d, rangeMm), rangeMm, config_.sideBaseMm, slope)) return;
  // The turns between the two readings each added their own error: the slope is an average over them.
  const int64_t q = config_.noise.turnMradPerQuarter;
  const int64_t turnVar = static_cast<int64_t>(slope.turns) * q * q;
  // A heading known this badly may show a larger slope than a straight wall's (3 sigma).
  const int32_t uncertain = 3 * static_cast<int32_t>(isqrt(static_cast<uint64_t>(tracker_.thetaVariance() + turnVar)));
  const int32_t slopeLimit = uncertain > config_.maxSideSlopeMrad ? uncertain : config_.maxSideSlopeMrad;
  if (abs32(slope.errorMrad) > slopeLimit) return;
  // Two readings, and the slip of what was driven towards or away from the wall in between (its 1 sigma).
  const int64_t slipMm = static_cast<int64_t>(slope.acrossPathMm) * config_.noise.slipPerMille / 1000;
  const int64_t spreadMm2 = 2 * tracker_.readingVariance() + slipMm * slipMm;
  const int64_t var = spreadMm2 * 1000000 / (static_cast<int64_t>(slope.baseMm) * slope.baseMm) + turnVar;
  (void)tracker_.measureHeading(tracker_.thetaMrad() + slope.errorMrad, static_cast<int32_t>(var > 1 ? var : 1));
}

bool Pilot::sideReadWanted(Sensor& s) const {
  if (config_.sideReadEveryMm <= 0) return false;
  for (int i = 0; i < kSensorCount; ++i) {
    const Sensor cand = static_cast<Sensor>(i);
    const Dir d = sensorDir(explorer_.pose().heading, cand);
    if (isVertical(d) == isVertical(explorer_.pose().heading)) continue;  // ahead or behind
    if (readHere_ & bitOf(d)) continue;
    // Again once far enough along from the last reading of the wall in this run; or a first one of a wall the
    // map shows beside the run (not more often than that either).
    const bool held = sides_.held(d);
    const bool due = sides_.sinceMm(d) >= config_.sideReadEveryMm;
    if ((held || !sides_.triedInRun(d) || due) && (held ? due : wallBeside(d))) {
      s = cand;
      return true;
    }
  }
  return false;
}

bool Pilot::wallBeside(Dir d) const {
  Cell c{};
  int16_t k = 0;
  return firstWall(d, c, k);
}

void Pilot::startRun() { sides_.turned(); }

void Pilot::observe(Sensor s, const RangeReading& r) {
  const Dir d = sensorDir(explorer_.pose().heading, s);
  readHere_ |= bitOf(d);
  sides_.tried(d);
  // A good reading, or an echo beyond the mapping range that only a known wall can explain.
  const bool far = r.status == RangeStatus::TooFar && r.cm > 0 && r.cm <= config_.poseRangeCm;
  if (!config_.correct || (r.status != RangeStatus::Good && !far)) return;
  if (isVertical(d) != isVertical(explorer_.pose().heading)) observeSide(d, static_cast<int32_t>(r.cm) * 10);
  int32_t faceMm = 0;
  Cell wall{};
  int32_t faceVar = 0;
#ifndef NXTMAP_NO_START_SQUARING
  // The face and the robot's offset learn from each other: whichever is known less well takes the reading.
  if (!knownWall(d, faceMm, wall, &faceVar) || faceVar > tracker_.varianceAlong(d)) {
    learnFace(d, r);
    return;
  }
#else
  if (!knownWall(d, faceMm, wall)) return;
#endif
  (void)tracker_.measure(d, faceMm - static_cast<int32_t>(r.cm) * 10, faceVar, straightFace(wall, d));
}

bool Pilot::poseReadWanted(Sensor& s) const {
  const int64_t limit = static_cast<int64_t>(config_.readAboveMm) * config_.readAboveMm;
  int64_t worst = limit;
  bool found = false;
  for (int i = 0; i < kSensorCount; ++i) {
    const Sensor cand = static_cast<Sensor>(i);
    const Dir d = sensorDir(explorer_.pose().heading, cand);
    if (readHere_ & bitOf(d)) continue;
    const int64_t v = tracker_.varianceAlong(d);
    int32_t faceMm = 0;
    Cell wall{};
    if (v > worst && knownWall(d, faceMm, wall)) {
      worst = v;
      s = cand;
      found = true;
    }
  }
  return found;
}

RangeReading Pilot::centred(Sensor s, RangeReading r) const {
  if (!config_.correct || !config_.centreReadings || r.status != RangeStatus::Good) return r;
  // The explorer measures from the cell's centre: add the robot's known offset along the beam.
  const RangeGeometry& g = explorer_.config().geometry;
  const int32_t along = tracker_.along(sensorDir(explorer_.pose().heading, s));
  int32_t cm = r.cm + (along >= 0 ? (along + 5) / 10 : -((-along + 5) / 10));
  if (cm <= g.minCm) cm = g.minCm + 1;
  if (cm > g.maxCm) cm = g.maxCm;
  r.cm = static_cast<int16_t>(cm);
  return r;
}

}  // namespace nxtmap
