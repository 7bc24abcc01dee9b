// HousePlanner, when a travel to an exit fails: a robot blocked by a wall its map does not have is lost by a cell
// or more; a standing scan moves its belief to the whole-cell shift that fits (StandingScan) and it tries once
// more, else the exit waits for a second try after the others.
#include <algorithm>

#include "host/house/HousePlanner.hpp"
#include "host/house/StandingScan.hpp"
#include "host/log/Log.hpp"

namespace nxtmap::house {

HouseOrder HousePlanner::failedPass() {
  // Blocked by a wall the map does not have there: the robot is lost by a cell or more.
  if (attempt_ == 0 && config_.relocaliseCells > 0) {
    facing_ = belief_.heading;
    phase_ = Phase::ScanBlocked;
    HouseOrder o;
    o.kind = HouseOrder::Kind::Scan;
    return o;
  }
  log::debug("house", "exit not passed: at %d,%d", belief_.cell.x, belief_.cell.y);
  relocalisedHere_ = false;
  notPassed();
  return nextExit();
}

void HousePlanner::notPassed() {
  if (current_.retry) {
    ++exitsUnreached_;
    return;
  }
  current_.retry = true;
  failed_.push_back(current_);
}

HouseOrder HousePlanner::scanned(const HouseReport& r) {
  const bool blocked = phase_ == Phase::ScanBlocked;
  const Cell shift = standingShift(r, blocked ? &facing_ : nullptr);
  const bool moved = shift.x != 0 || shift.y != 0;
  if (moved) {
    belief_.cell = offset(belief_.cell, shift.x, shift.y);
    ++relocalisations_;
    log::debug("house", "relocalised by %d,%d", shift.x, shift.y);
  }
  if (blocked) {
    if (!moved) {
      relocalisedHere_ = false;
      notPassed();
      return nextExit();
    }
    attempt_ = 1;
    return passExit();
  }
  if (moved) {
    relocalisedHere_ = true;
    return nextExit();
  }
  exitsUnreached_ += static_cast<int>(pending_.size());
  pending_.clear();
  return endOfExits();
}

Cell HousePlanner::standingShift(const HouseReport& r, const Dir* blocked) const {
  const int reachCm = std::max<int>(geometry_.maxCm, config_.poseRangeCm);
  std::vector<StandingReading> readings;
  for (int i = 0; i < kSensorCount; ++i) {
    const RangeReading& rr = r.scan[i];
    if (rr.status == RangeStatus::Inconsistent) continue;  // says nothing
    StandingReading s;
    s.dir = sensorDir(belief_.heading, static_cast<Sensor>(i));
    s.echo = rr.status == RangeStatus::Good || rr.status == RangeStatus::TooNear ||
             (rr.status == RangeStatus::TooFar && rr.cm > 0 && rr.cm <= reachCm);
    s.cm = rr.status == RangeStatus::TooNear ? geometry_.minCm : rr.cm;
    readings.push_back(s);
  }
  return bestStandingShift(known_, belief_.cell, readings, geometry_, reachCm, blocked, config_.relocaliseCells);
}

}  // namespace nxtmap::house
