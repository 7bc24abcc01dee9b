#include "common/explore/PropagationExplorer.hpp"

namespace nxtmap {
namespace {
// Four transitions without a diagonal step: the robot went round the room along its walls and
// is about to repeat that lap, which the stop heuristic counts as a reused path.
constexpr uint8_t kMaxIdleTransitions = 4;
}  // namespace

Action PropagationExplorer::decide() {
  switch (phase_) {
    case Phase::Startup: return startup();
    case Phase::AtStart: return atStart();
    case Phase::Mid: return mid();
    case Phase::Deviate: return deviate();
    case Phase::Return: return begin(prop_);  // arrived on the start line
    case Phase::Sweep: return sweep();
    case Phase::SweepTravel:
      if (bigArea_) return startup();  // map the large area with a propagation of its own
      return sweep();
  }
  return Action::done();
}

void PropagationExplorer::onBlocked() {
  // Only with noise or a real robot: re-evaluate from where the robot is.
  if (phase_ == Phase::Mid || phase_ == Phase::Deviate) phase_ = Phase::AtStart;
}

// Start-up heuristic (3.5.1): of the four sides as seen from here, go towards the larger
// vertical one and the larger horizontal one; this fixes the frame's quadrant.
Action PropagationExplorer::startup() {
  const Cell c = pose_.cell;
  const int sy = openCells(c, Dir::North) >= openCells(c, Dir::South) ? 1 : -1;
  const int sx = openCells(c, Dir::East) >= openCells(c, Dir::West) ? 1 : -1;
  idleTransitions_ = 0;
  return begin(propagationOf(sx, sy));
}

Action PropagationExplorer::begin(Propagation p) {
  prop_ = p;
  origin_ = pose_.cell;
  phase_ = Phase::AtStart;
  return atStart();
}

// Step 1 of every propagation: one diagonal step, as two straight moves (4.7.1).
Action PropagationExplorer::atStart() {
  const Cell c = pose_.cell;
  const int sx = propagationDx(prop_), sy = propagationDy(prop_);
  if (map_.diagonalUsed(c, sx, sy)) return ended(PropagationOutcome::Reused);
  const Dir v = verticalDir(prop_), h = horizontalDir(prop_);
  const bool freeV = passable(advance(c, v)) && canHead(v), freeH = passable(advance(c, h)) && canHead(h);
  if (!freeV && !freeH) return ended(PropagationOutcome::Corner);
  first_ = freeV ? v : h;  // forward (or backward) first, sideways when that is blocked
  second_ = freeV ? h : v;
  stepFrom_ = c;
  phase_ = Phase::Mid;
  go(first_);
  return follow();
}

Action PropagationExplorer::mid() {
  const int sx = propagationDx(prop_), sy = propagationDy(prop_);
  const Cell target = offset(stepFrom_, sx, sy);
  if (passable(target) && canHead(second_)) {
    map_.setDiagonalUsed(stepFrom_, sx, sy);
    idleTransitions_ = 0;
    phase_ = Phase::AtStart;
    go(second_);
    return follow();
  }
  // The diagonal cell is blocked: go straight on along the obstacle (steps 2 and 3).
  wallCount_ = 1;
  phase_ = Phase::Deviate;
  return deviate();
}

// Deviation: moving straight along `first_` while the side `second_` is blocked, counting
// the blocked cells beside (wall detection, 3.5.4 and 4.7.3).
Action PropagationExplorer::deviate() {
  const Cell p = pose_.cell;
  if (passable(advance(p, second_))) return atStart();  // obstacle passed: back to step 1
  const bool sideIsVertical = isVertical(second_);
  if (wallCount_ > config_.minWallCells) {
    return ended(sideIsVertical ? PropagationOutcome::HitVertical : PropagationOutcome::HitHorizontal);
  }
  if (!passable(advance(p, first_))) return ended(PropagationOutcome::Corner);
  ++wallCount_;
  go(first_);
  return follow();
}

Action PropagationExplorer::ended(PropagationOutcome o) {  // o may be rewritten to Reused
  log_[records_ % kLogCapacity] = Record{prop_, o, pose_.cell};
  ++records_;
  const Propagation next = nextPropagation(prop_, o);
  if (o != PropagationOutcome::Reused && ++idleTransitions_ >= kMaxIdleTransitions) {
    log_[records_ % kLogCapacity] = Record{next, PropagationOutcome::Reused, pose_.cell};
    ++records_;
    o = PropagationOutcome::Reused;
  }
  if (o == PropagationOutcome::Reused) {
    phase_ = Phase::Sweep;  // stop heuristic (3.5.3)
    return sweep();
  }
  if (o != PropagationOutcome::Corner) return begin(next);
  // Corner: success. Back to the propagation's vertical or horizontal start line, whichever is
  // nearer, then the opposite propagation.
  onRow_ = Cell{pose_.cell.x, origin_.y};
  onColumn_ = Cell{origin_.x, pose_.cell.y};
  target_ = Cell{};
  targetCost_ = 0xFFFF;
  found_ = 0;
  next_ = next;
  return startSearch(kReturnLine);
}

bool PropagationExplorer::searchVisit(uint8_t purpose, Cell c, uint16_t cost) {
  if (purpose == kReturnLine) {
    if (c == onRow_ || c == onColumn_) {
      if (cost < targetCost_) {
        target_ = c;
        targetCost_ = cost;
      }
      ++found_;
    }
    return found_ == 2 || (onRow_ == onColumn_ && found_ == 1);
  }
  int16_t g = 0;
  for (int d = 0; d < 4; ++d) g = static_cast<int16_t>(g + unknownAhead(c, static_cast<Dir>(d)));
  if (g == 0) return false;
  target_ = c;
  targetCost_ = cost;
  gain_ = g;
  return true;
}

Action PropagationExplorer::searchDone(uint8_t purpose) {
  if (purpose == kReturnLine) {
    prop_ = next_;
    if (targetCost_ == 0 || targetCost_ == 0xFFFF || !travelTo(target_, targetCost_)) return begin(next_);
    phase_ = Phase::Return;
    return follow();
  }
  if (gain_ == 0 || !travelTo(target_, targetCost_)) return Action::done();
  bigArea_ = gain_ >= config_.bigAreaCells;
  phase_ = Phase::SweepTravel;
  return follow();
}

// After the stop heuristic: go to the nearest spot from which unknown cells can still be read.
Action PropagationExplorer::sweep() {
  ++sweeps_;
  target_ = Cell{};
  targetCost_ = 0;
  gain_ = 0;
  return startSearch(kSweepTarget);
}

}  // namespace nxtmap
