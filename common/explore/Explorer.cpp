#include "common/explore/Explorer.hpp"

#include "common/check/Check.hpp"
#include "common/sensing/RayMarker.hpp"

namespace nxtmap {

Explorer::Explorer(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config)
    : map_(map), planner_(planner), config_(config) {
  planner_.setTurnNeedsRoom(config.turnNeedsRoom);
#ifndef NXTMAP_NO_START_SQUARING
  planner_.setNoTurn(&stalledTurns_);
#endif
}

bool Explorer::canHead(Dir d) const {
#ifndef NXTMAP_NO_START_SQUARING
  if (isVertical(d) != isVertical(pose_.heading) && stalledTurns_.contains(pose_.cell)) return false;
#endif
  return isVertical(d) == isVertical(pose_.heading) || !config_.turnNeedsRoom || roomWaived() ||
         TravelPlanner::roomToTurn(map_.grid(), pose_.cell);
}

#ifndef NXTMAP_NO_START_SQUARING
bool Explorer::StalledTurns::contains(Cell c) const {
  for (uint8_t i = 0; i < count; ++i)
    if (cells[i] == c) return true;
  return false;
}

void Explorer::waiveRoom(bool on) {
  roomWaived_ = on;
  planner_.setTurnNeedsRoom(config_.turnNeedsRoom && !on);
}
#endif

Action Explorer::finish(ExplorerEnd why) {
  end_ = why;
  route_.clear();
  return Action::done();
}

void Explorer::apply(const Event& e) {
  switch (e.kind) {
    case Event::Kind::Start:
      pose_ = e.pose;
      startCell_ = e.pose.cell;
      started_ = true;
      if (!map_.markVisited(pose_.cell)) end_ = ExplorerEnd::GridFull;
      break;
    case Event::Kind::Range: {
      ++counters_.sensorRequests;
      counters_.rawSamples += e.reading.samples;
      const Dir d = sensorDir(pose_.heading, e.sensor);
      // Where it was set down the robot takes its blind zone as clear (a robot is put down in the open), and
      // where its body has turned a quarter on the spot (ExplorerConfig::turnNeedsRoom); everywhere else only
      // what it saw from farther away (RangeGeometry::blindCm).
      const bool trusted = pose_.cell == startCell_ || (turnedHere_ && config_.turnNeedsRoom);
      const RayMarkResult r = markRay(map_, config_.geometry, pose_.cell, d, e.reading, trusted);
      if (r.conclusive) map_.setRead(pose_.cell, d);
      if (r.cellsMarked == 0 && !trusted && config_.turnNeedsRoom && e.reading.status == RangeStatus::NoEcho)
        blindDirs_ = static_cast<uint8_t>(blindDirs_ | (1u << static_cast<int>(d)));
      break;
    }
    case Event::Kind::Moved: {
      const int8_t n = e.amount < 0 ? static_cast<int8_t>(-e.amount) : e.amount;
      const Dir d = e.amount > 0 ? pose_.heading : opposite(pose_.heading);
      for (int8_t i = 0; i < n; ++i) {
        pose_.cell = advance(pose_.cell, d);
        if (!map_.markVisited(pose_.cell)) end_ = ExplorerEnd::GridFull;
        if (!route_.empty() && route_.front() == d) route_.pop();
      }
      if (n > 0) {
        turnedHere_ = false;
        blindDirs_ = 0;
      }
#ifndef NXTMAP_NO_START_SQUARING
      if (roomWaived_ && route_.empty()) waiveRoom(false);  // reached: turn only with room again
#endif
      counters_.cellsMoved += static_cast<uint32_t>(n);
      break;
    }
    case Event::Kind::Blocked:
      ++counters_.blockedMoves;
      if (e.amount != 0) blindDirs_ = 0;  // a turn met something: the blind zone stays untrusted here
#ifndef NXTMAP_NO_START_SQUARING
      if (roomWaived_) waiveRoom(false);
#endif
#ifndef NXTMAP_NO_START_SQUARING
      if (e.amount != 0 && !stalledTurns_.full()) {  // a turn stalled here: never again
        if (!stalledTurns_.contains(pose_.cell)) stalledTurns_.cells[stalledTurns_.count++] = pose_.cell;
        route_.clear();
        break;
      }
#endif
      if (e.amount == 0 ? !map_.observeBlocked(advance(pose_.cell, pendingMove_))
                        : !map_.observeOccupied(advance(pose_.cell, pendingMove_)))
        end_ = ExplorerEnd::GridFull;
      route_.clear();
      break;
    case Event::Kind::Turned:
      // Explorers turn in quarters; a 45 degree turn is counted for time but kept on the axis
      // grid by its pair.
      pose_.heading = rotate(pose_.heading, e.amount / 2);
      if (e.amount / 2 != 0 && !turnedHere_) {  // the blind zone is now trusted: read again what it hid
        turnedHere_ = true;
        map_.forgetReads(pose_.cell, blindDirs_);
        blindDirs_ = 0;
      }
      counters_.turnEighths += static_cast<uint32_t>(e.amount < 0 ? -e.amount : e.amount);
      break;
    case Event::Kind::Thought: break;
  }
}

Action Explorer::settle(const Action& a) {
  if (a.kind != Action::Kind::Done) return a;
    // Nothing left within reach turning only where the body has room: try once more turning anywhere (a turn
    // that meets something is turned back by the pilot and heard as Event::turnBlocked).
#ifndef NXTMAP_NO_START_SQUARING  // the RAM-run image has no room for it (nor the pilot's stall recovery)
  if (config_.turnNeedsRoom && !roomWaived_ && !stalledTurns_.full()) {
    waiveRoom(true);
    return settle(decide());
  }
#endif
  if (!proving_ && config_.turnNeedsRoom && config_.geometry.blindCells() > 0) {  // last: where the blind zone hid
    proving_ = true;
    scanRow_ = map_.grid().window().minY;
    forgotten_ = 0;
    return Action::think();  // the scan runs in slices (continueProveScan)
  }
#ifndef NXTMAP_NO_START_SQUARING
  // Still nothing, with turns refused where one stalled: a stall says as much about where in its cell the robot
  // stood as about the cell (a robot trapped by its own stalls gave up with most of a room unknown). Before giving
  // up, the stalls are forgotten once and the robot looks again, turning anywhere.
  if (!retriedStalls_ && stalledTurns_.count > 0) {
    retriedStalls_ = true;
    stalledTurns_.count = 0;
    if (config_.turnNeedsRoom) waiveRoom(true);
    return settle(decide());
  }
#endif
  return finish(ExplorerEnd::Complete);
}

Action Explorer::continueProveScan() {
  const Bounds w = map_.grid().window();
  for (int16_t rows = 0; rows < kProveScanRows && scanRow_ <= w.maxY; ++rows, ++scanRow_) {
    for (int16_t x = w.minX; x <= w.maxX; ++x) forgetBlindReads(Cell{x, scanRow_});
  }
  if (scanRow_ <= w.maxY) return Action::think();
  scanRow_ = kNoScan;
  if (forgotten_ == 0) return finish(ExplorerEnd::Complete);
  Sensor s;  // the robot's own cell may be among them
  return nextRead(s) ? Action::read(s) : settle(decide());
}

void Explorer::forgetBlindReads(Cell c) {
  const uint8_t read = map_.readDirs(c);
  if (read == 0) return;  // most cells of the window: never stood on
  uint8_t dirs = 0;
  for (int d = 0; d < 4; ++d) {
    if (((read >> d) & 1u) == 0) continue;
    const Cell n = advance(c, static_cast<Dir>(d));
    if (map_.at(n) == CellState::Unknown && map_.grid().fits(n)) dirs = static_cast<uint8_t>(dirs | (1u << d));
  }
  if (dirs == 0) return;
  map_.forgetReads(c, dirs);
  ++forgotten_;
}

bool Explorer::proveTurnDue() const {
  if (!proving_ || blindDirs_ == 0 || turnedHere_) return false;
#ifndef NXTMAP_NO_START_SQUARING
  if (stalledTurns_.contains(pose_.cell)) return false;
#endif
  return route_.empty() || isVertical(route_.front()) == isVertical(pose_.heading);  // else the route turns
}

Action Explorer::startSearch(uint8_t purpose) {
  planner_.start(pose_);  // clears the planner's labels: a slice of its own
  searching_ = true;
  searchPurpose_ = purpose;
  return Action::think();
}

Action Explorer::continueSearch() {
  const uint8_t purpose = searchPurpose_;
  if (searchEnded_) {  // the strategy's decision (a route walked back from far off) in a slice of its own
    searching_ = searchEnded_ = false;
    return searchDone(purpose);
  }
  const TravelPlanner::Status st = planner_.proceed(
      map_.grid(), [this, purpose](Cell c, uint16_t cost) { return searchVisit(purpose, c, cost); },
      config_.searchSliceStates);
  searchEnded_ = st != TravelPlanner::Status::Running;
  return Action::think();
}

bool Explorer::searchVisit(uint8_t, Cell, uint16_t) { return true; }

Action Explorer::searchDone(uint8_t) { return Action::done(); }

Action Explorer::step(const Event& e) {
  const Action a = next(e);
  if (a.kind != Action::Kind::Think) {
    thinks_ = 0;
    return a;
  }
  return ++thinks_ > kMaxThinks ? finish(ExplorerEnd::ActionLimit) : a;
}

Action Explorer::next(const Event& e) {
  if (end_ != ExplorerEnd::Running) return Action::done();
  if (searching_) {
    NXTMAP_CHECK(e.kind == Event::Kind::Thought);  // nothing else can happen while thinking
    return settle(continueSearch());
  }
  if (scanRow_ != kNoScan) {
    NXTMAP_CHECK(e.kind == Event::Kind::Thought);
    return continueProveScan();
  }
  if (!started_ && e.kind != Event::Kind::Start) apply(Event::start());
  apply(e);
  if (end_ != ExplorerEnd::Running) return finish(end_);
  if (++actions_ > config_.maxActions) return finish(ExplorerEnd::ActionLimit);
  if (e.kind == Event::Kind::Blocked) onBlocked();
  Sensor s;
  if (nextRead(s)) return Action::read(s);
  if (proveTurnDue()) return Action::turn(2);  // a quarter on the spot proves the blind zone clear
  return settle(route_.empty() ? decide() : follow());
}

int16_t Explorer::unknownAhead(Cell c, Dir d) const {
  if (map_.wasRead(c, d)) return 0;
  int16_t unknown = 0;
  const int16_t reach = config_.geometry.hitCells();
  // Stepped a cell at a time (the frontier search asks this of every cell it passes: the brick's
  // costliest decisions are mostly this loop).
  const int16_t sx = dx(d), sy = dy(d);
  Cell n = c;
  for (int16_t k = 1; k <= reach; ++k) {
    n.x = static_cast<int16_t>(n.x + sx);
    n.y = static_cast<int16_t>(n.y + sy);
    const CellState st = map_.at(n);
    if (st == CellState::Occupied) break;
    if (st == CellState::Unknown) {
      if (!map_.grid().fits(n)) break;
      ++unknown;
    }
  }
  return unknown;
}

bool Explorer::worthReading(Cell c, Dir d) const { return unknownAhead(c, d) > 0; }

bool Explorer::nextRead(Sensor& s) const {
  for (int i = 0; i < kSensorCount; ++i) {
    const Sensor cand = static_cast<Sensor>(i);
    if (worthReading(pose_.cell, sensorDir(pose_.heading, cand))) {
      s = cand;
      return true;
    }
  }
  return false;
}

int16_t Explorer::openCells(Cell c, Dir d) const {
  int16_t n = 0;
  while (map_.at(advance(c, d, static_cast<int16_t>(n + 1))) == CellState::Free) ++n;
  return n;
}

void Explorer::go(Dir d) {
  route_.clear();
  route_.push(d);
}

bool Explorer::travelTo(Cell target, uint16_t cost) { return planner_.routeTo(map_.grid(), target, cost, route_); }

Action Explorer::follow() {
  const Dir d = route_.front();
  if (!map_.grid().isFree(advance(pose_.cell, d)) || !canHead(d)) {  // the map changed under the route
    route_.clear();
    return decide();
  }
  pendingMove_ = d;
  if (pose_.heading == d) return Action::move(1);
  if (pose_.heading == opposite(d)) return Action::move(-1);
  return Action::turn(rotate(pose_.heading, 1) == d ? 2 : -2);
}

}  // namespace nxtmap
