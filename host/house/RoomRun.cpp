#include "host/house/RoomRun.hpp"

#include "host/mapping/SimDrive.hpp"

#include <algorithm>
#include <deque>

namespace nxtmap::house {
namespace {
constexpr uint8_t kMaxFound = 32;
// Cells closed beyond each end of the entrance's line: under noise a doorway can be found a cell
// or two narrower than it is, and the robot would slip back past its closed cells into the room
// it came from. (Not for the room's own exits: there the cells beyond may be the way on.)
constexpr int16_t kGuardCells = 2;

bool overlaps(const Doorway& a, const Doorway& b) {
  for (int16_t i = 0; i < a.width; ++i) {
    for (int16_t j = 0; j < a.depth; ++j) {
      if (b.contains(a.cell(i, j))) return true;
    }
  }
  return false;
}
}  // namespace

RoomRun::RoomRun(sim::SimRobot& robot, const ExplorerConfig& config, mapping::Strategy strategy,
                 const DoorwayLimits& doorways, std::vector<Cell> entrance, const PilotConfig& pilot,
                 const RoomLimits& roomLimits)
    : robot_(robot),
      config_(config),
      doorwayLimits_(doorways),
      storage_(std::make_unique<Storage>()),
      entrance_(std::move(entrance)),
      roomLimits_(roomLimits) {
  map_ = std::make_unique<MapLayers>(storage_->map.view(), Storage::kWidth(), Storage::kHeight());
  planner_ = std::make_unique<TravelPlanner>(storage_->travel.view(), Storage::kWidth(), Storage::kHeight());
  if (strategy == mapping::Strategy::Propagation) {
    propagation_ = std::make_unique<PropagationExplorer>(*map_, *planner_, config_);
    explorer_ = propagation_.get();
  } else {
    frontier_ = std::make_unique<FrontierExplorer>(*map_, *planner_, config_);
    explorer_ = frontier_.get();
  }
  pilot_ = std::make_unique<Pilot>(*explorer_, pilot);
  closeEntrance();
  updateShut();
  closeDoors();
  last_ = pilot_->step(DriveEvent::start());
}

RoomRun::~RoomRun() = default;

// Every Drive carries out one explorer move of one cell (forward for value > 0).
bool RoomRun::drivesIntoClosed(const DriveAction& a) const {
  if (a.kind != DriveAction::Kind::Drive) return false;
  const Pose& p = explorer_->pose();
  const Cell next = advance(p.cell, a.value > 0 ? p.heading : opposite(p.heading));
  return std::find(shut_.begin(), shut_.end(), next) != shut_.end();
}

void RoomRun::closeDoors() {
  for (const Cell c : shut_) (void)map_->markBlocked(c);
}

void RoomRun::updateShut() {
  shut_ = closed_;
  shut_.insert(shut_.end(), guards_.begin(), guards_.end());
  // Held shut, not seen: the pilot must not take them for walls to read its pose from.
  pilot_->setVirtualWalls(shut_.data(), static_cast<uint16_t>(shut_.size()));
}

void RoomRun::closeEntrance() {
  const std::vector<Cell>& cells = entrance_;
  if (cells.empty()) return;
  closed_.insert(closed_.end(), cells.begin(), cells.end());
  Bounds b{cells[0].x, cells[0].y, cells[0].x, cells[0].y};
  for (const Cell c : cells) {
    b.minX = std::min(b.minX, c.x);
    b.minY = std::min(b.minY, c.y);
    b.maxX = std::max(b.maxX, c.x);
    b.maxY = std::max(b.maxY, c.y);
  }
  const bool alongX = b.width() >= b.height();
  for (int16_t k = 1; k <= kGuardCells; ++k) {
    if (alongX) {
      for (int16_t y = b.minY; y <= b.maxY; ++y) {
        guards_.push_back(Cell{static_cast<int16_t>(b.minX - k), y});
        guards_.push_back(Cell{static_cast<int16_t>(b.maxX + k), y});
      }
    } else {
      for (int16_t x = b.minX; x <= b.maxX; ++x) {
        guards_.push_back(Cell{x, static_cast<int16_t>(b.minY - k)});
        guards_.push_back(Cell{x, static_cast<int16_t>(b.maxY + k)});
      }
    }
  }
}

std::vector<uint8_t> RoomRun::reach(const std::vector<Cell>& closed, Bounds& box) const {
  box = map_->grid().window();
  const int w = box.width(), h = box.height();
  std::vector<uint8_t> seen(static_cast<size_t>(w) * static_cast<size_t>(h), 0);
  const auto idx = [&](Cell c) { return static_cast<size_t>((c.y - box.minY) * w + (c.x - box.minX)); };
  const auto open = [&](Cell c) {
    return box.contains(c) && map_->grid().isFree(c) && std::find(closed.begin(), closed.end(), c) == closed.end();
  };
  // The start cell always counts (the robot stood there), whatever noise later said about it.
  const Cell start{0, 0};
  if (!box.contains(start)) return seen;
  std::deque<Cell> queue{start};
  seen[idx(start)] = 1;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (int d = 0; d < 4; ++d) {
      const Cell n = advance(c, static_cast<Dir>(d));
      if (!open(n) || seen[idx(n)]) continue;
      seen[idx(n)] = 1;
      queue.push_back(n);
    }
  }
  return seen;
}

void RoomRun::lookForDoorways() {
  const Cell p = explorer_->pose().cell;
  const int16_t r = static_cast<int16_t>(config_.geometry.hitCells() + doorwayLimits_.maxWidth + 2);
  Bounds area{static_cast<int16_t>(p.x - r), static_cast<int16_t>(p.y - r), static_cast<int16_t>(p.x + r),
              static_cast<int16_t>(p.y + r)};
  const Bounds win = map_->grid().window();
  area.minX = std::max(area.minX, win.minX);
  area.minY = std::max(area.minY, win.minY);
  area.maxX = std::min(area.maxX, win.maxX);
  area.maxY = std::min(area.maxY, win.maxY);
  Doorway found[kMaxFound];
  const uint8_t n = findDoorways(map_->grid(), area, doorwayLimits_, found, kMaxFound);
  bool changed = false;
  for (uint8_t i = 0; i < n; ++i) {
    const Doorway& d = found[i];
    if (!wellSeen(d)) continue;
    bool known = false;
    for (Doorway& c : candidates_) {
      if (!overlaps(d, c) && !overlaps(c, d)) continue;
      known = true;
      if (!(c == d)) {
        c = d;
        changed = true;
      }
    }
    if (!known) {
      candidates_.push_back(d);
      changed = true;
    }
  }
  if (changed || (++sinceCheck_ >= kRecheckSteps && !candidates_.empty())) evaluateCandidates();
}

bool RoomRun::wellSeen(const Doorway& d) const {
  // Under noise one stray reading can open a gap in a wall or put a "jamb" in the open: the
  // jambs must be surely occupied and every gap cell surely free (evidence, see MapLayers).
  const auto jamb = [&](Cell c) { return map_->evidence(c) >= kSureEvidence; };
  for (int16_t b = 0; b < d.depth; ++b) {
    if (!jamb(d.cell(-1, b)) || !jamb(d.cell(d.width, b))) return false;
    for (int16_t a = 0; a < d.width; ++a) {
      if (map_->evidence(d.cell(a, b)) > -kSureEvidence) return false;
    }
  }
  return true;
}

void RoomRun::evaluateCandidates() {
  sinceCheck_ = 0;
  // Close every candidate at once (several doorways may lead into the same room), then keep as
  // exits those whose far side is cut off from the start while the robot is on the start's side.
  std::vector<Cell> closed = shut_;
  for (const Doorway& d : candidates_) {
    for (int16_t a = 0; a < d.width; ++a) {
      for (int16_t b = 0; b < d.depth; ++b) closed.push_back(d.cell(a, b));
    }
  }
  Bounds box;
  const std::vector<uint8_t> seen = reach(closed, box);
  const auto reached = [&](Cell c) {
    return box.contains(c) && seen[static_cast<size_t>((c.y - box.minY) * box.width() + (c.x - box.minX))] != 0;
  };
  if (!reached(explorer_->pose().cell)) return;  // the robot is beyond some doorway: decide later
  std::vector<Doorway> still;
  for (const Doorway& d : candidates_) {
    bool low = false, high = false;
    for (int16_t a = 0; a < d.width; ++a) {
      low = low || reached(d.cell(a, -1));
      high = high || reached(d.cell(a, d.depth));
    }
    if (low == high) {
      still.push_back(d);
      continue;
    }
    RoomExit e;
    for (int16_t a = 0; a < d.width; ++a) {
      for (int16_t b = 0; b < d.depth; ++b) e.cells.push_back(d.cell(a, b));
    }
    e.depth = d.depth;
    const int16_t mid = static_cast<int16_t>((d.width - 1) / 2);
    e.inside = low ? d.cell(mid, -1) : d.cell(mid, d.depth);
    e.outward = d.alongX ? (low ? Dir::North : Dir::South) : (low ? Dir::East : Dir::West);
    closed_.insert(closed_.end(), e.cells.begin(), e.cells.end());
    exits_.push_back(std::move(e));
  }
  candidates_ = std::move(still);
  updateShut();
  closeDoors();
}

void RoomRun::runToEnd() {
  while (!pilot_->finished()) {
    // A move decided just before a doorway was closed meets the closed doorway like a wall.
    const DriveEvent e =
        drivesIntoClosed(last_) ? DriveEvent::driven(true) : mapping::carryOutOnRobot(robot_, last_, config_.geometry);
    moved_ = moved_ || last_.kind == DriveAction::Kind::Drive || last_.kind == DriveAction::Kind::Rotate;
    if (!moved_ && e.kind == DriveEvent::Kind::Range)
      startReadings_.push_back(StartReading{sensorDir(explorer_->pose().heading, e.sensor), e.reading});
    last_ = pilot_->step(e);
    closeDoors();
    if (!pilot_->finished()) lookForDoorways();
  }
  // Hand the robot over on its axis as far as it is known (see handOverHeadingVariance).
  const DriveAction level = pilot_->levelling();
  if (level.kind == DriveAction::Kind::Rotate) (void)mapping::carryOutOnRobot(robot_, level, config_.geometry);
  finish();
}

void RoomRun::finish() {
  // Open the doorways again: they are free (they were seen free before they were closed).
  for (const Cell c : closed_) {
    for (int k = 0; k < 16 && map_->grid().isOccupied(c); ++k) (void)map_->observeFree(c);
  }
  interpretation_ = interpretRoom(map_->grid(), roomLimits_, doorwayLimits_);
  // Cut the map to the room: reachable cells without crossing a doorway, their 8 neighbours,
  // and the doorways themselves.
  Bounds box;
  const std::vector<uint8_t> seen = reach(closed_, box);
  network::RoomMap full = network::RoomMap::fromGrid(map_->grid());
  network::RoomMap cut(full.minX(), full.minY(), full.width(), full.height());
  const auto reached = [&](Cell c) {
    return box.contains(c) && seen[static_cast<size_t>((c.y - box.minY) * box.width() + (c.x - box.minX))] != 0;
  };
  // An exit found while the robot was beyond another doorway may join two other rooms: only the
  // exits of this room (their inside cell in the room) are kept; the others are found again there.
  std::vector<RoomExit> kept;
  std::vector<Cell> doors = entrance_;
  for (RoomExit& e : exits_) {
    if (!reached(e.inside)) continue;
    doors.insert(doors.end(), e.cells.begin(), e.cells.end());
    kept.push_back(std::move(e));
  }
  exits_ = std::move(kept);
  for (int y = full.minY(); y <= full.maxY(); ++y) {
    for (int x = full.minX(); x <= full.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      bool keep = reached(c) || std::find(doors.begin(), doors.end(), c) != doors.end();
      for (int dy = -1; dy <= 1 && !keep; ++dy) {
        for (int dx = -1; dx <= 1 && !keep; ++dx) keep = reached(offset(c, dx, dy));
      }
      if (keep) cut.set(c, full.at(c));
    }
  }
  roomMap_ = std::move(cut);
  fullMap_ = std::move(full);
}

}  // namespace nxtmap::house
