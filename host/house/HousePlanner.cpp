#include "host/house/HousePlanner.hpp"

#include <algorithm>
#include <limits>

#include "host/house/TravelDistances.hpp"
#include "host/log/Log.hpp"

namespace nxtmap::house {

std::vector<Cell> cellsOf(const Doorway& door) {
  std::vector<Cell> cells;
  for (int16_t a = 0; a < door.width; ++a) {
    for (int16_t b = 0; b < door.depth; ++b) cells.push_back(door.cell(a, b));
  }
  return cells;
}

RoomExit transformExit(const RoomExit& e, const network::RoomTransform& t) {
  std::vector<Cell> cells = cellsOf(e.door);
  for (Cell& c : cells) c = t.apply(c);
  RoomExit out;
  out.door = doorwayAround(cells.data(), static_cast<int>(cells.size()));
  out.door.depth = e.door.depth;
  out.door.width = e.door.width;
  out.door.alongX = (t.quarterTurns() % 2 == 0) ? e.door.alongX : !e.door.alongX;
  out.inside = t.apply(e.inside);
  out.outward = t.apply(e.outward);
  return out;
}

HousePlanner::HousePlanner(const HousePlannerConfig& config, const RangeGeometry& geometry)
    : config_(config), geometry_(geometry) {}

HouseOrder HousePlanner::start() {
  phase_ = Phase::FirstRoom;
  belief_ = Pose{};
  brickToHouse_ = network::RoomTransform{};
  HouseOrder o;
  o.kind = HouseOrder::Kind::ExploreFirstRoom;
  return o;
}

HouseOrder HousePlanner::on(const HouseReport& r) {
  switch (phase_) {
    case Phase::FirstRoom:
      if (r.kind != HouseReport::Kind::RoomMapped) break;
      recordRoom(r, -1, nullptr, {});
      relocalisedHere_ = false;
      return nextExit();
    case Phase::Travel:
      belief_ = Pose{brickToHouse_.apply(r.pose.cell), brickToHouse_.apply(r.pose.heading)};
      if (r.kind != HouseReport::Kind::Arrived) return failedPass();
      // A leg of a long way: the next one (the exit's inside cell reached: through it).
      return passExit();
    case Phase::Cross: {
      if (r.kind == HouseReport::Kind::CrossBlocked) {
        belief_ = Pose{brickToHouse_.apply(r.pose.cell), brickToHouse_.apply(r.pose.heading)};
        return failedPass();
      }
      if (r.kind != HouseReport::Kind::RoomMapped) break;
      // The new room's frame starts where the crossing ended, as the robot believes it.
      belief_ = Pose{brickToHouse_.apply(r.crossedAt.cell), brickToHouse_.apply(r.crossedAt.heading)};
      const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(current_.room)];
      std::vector<Cell> entranceHouse = cellsOf(current_.exit.door);
      for (Cell& c : entranceHouse) c = owner.toHouse.apply(c);
      const Pending via = current_;
      recordRoom(r, via.room, &via.exit, entranceHouse);
      relocalisedHere_ = false;
      return nextExit();
    }
    case Phase::ScanNoExit:
    case Phase::ScanBlocked:
      if (r.kind == HouseReport::Kind::Scanned) return scanned(r);
      break;
    case Phase::Done: break;
  }
  log::warn("house", "report %d not expected now (phase %d): ignored", static_cast<int>(r.kind),
            static_cast<int>(phase_));
  HouseOrder o;
  o.kind = HouseOrder::Kind::Finished;
  phase_ = Phase::Done;
  return o;
}

network::RoomMap HousePlanner::knownForTravel() const {
  network::HouseNetwork all = network_;
  for (const network::RoomNode& n : seen_) all.addRoom(n);
  return all.merged();
}

HouseOrder HousePlanner::nextExit() {
  for (;;) {
    if (pending_.empty() || static_cast<int>(network_.rooms().size()) >= config_.maxRooms) return endOfExits();
    // Exits into rooms already mapped become gateways without a run.
    pending_.erase(
        std::remove_if(pending_.begin(), pending_.end(), [&](const Pending& p) { return leadsToMappedRoom(p); }),
        pending_.end());
    if (pending_.empty()) return endOfExits();
    known_ = knownForTravel();
    const std::vector<int> dist = travelDistances(known_, belief_.cell);
    size_t best = pending_.size();
    int bestDist = std::numeric_limits<int>::max();
    for (size_t i = 0; i < pending_.size(); ++i) {
      const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(pending_[i].room)];
      const Cell in = owner.toHouse.apply(pending_[i].exit.inside);
      if (!known_.inside(in)) continue;
      const int d = dist.empty()
                        ? -1
                        : dist[static_cast<size_t>((in.y - known_.minY()) * known_.width() + (in.x - known_.minX()))];
      if (d >= 0 && d < bestDist) {
        bestDist = d;
        best = i;
      }
    }
    // Nothing reachable from the believed cell: the robot may be lost in a pocket of the map.
    if (best == pending_.size() && !relocalisedHere_ && config_.relocaliseCells > 0) {
      phase_ = Phase::ScanNoExit;
      HouseOrder o;
      o.kind = HouseOrder::Kind::Scan;
      return o;
    }
    if (best == pending_.size()) {  // nothing left that can be reached
      log::debug("house", "no reachable exit among %zu", pending_.size());
      exitsUnreached_ += static_cast<int>(pending_.size());
      pending_.clear();
      return endOfExits();
    }
    current_ = pending_[best];
    pending_.erase(pending_.begin() + static_cast<long>(best));
    attempt_ = 0;
    return passExit();
  }
}

HouseOrder HousePlanner::endOfExits() {
  // The exits a travel could not pass get one more try each, from wherever the robot is now (another way there,
  // or the same one better placed: a travel is most often blocked where the robot was a cell off).
  if (!failed_.empty() && static_cast<int>(network_.rooms().size()) < config_.maxRooms) {
    pending_.swap(failed_);
    failed_.clear();
    relocalisedHere_ = false;
    return nextExit();
  }
  if (queueOpening()) {
    relocalisedHere_ = false;
    return nextExit();
  }
  exitsUnreached_ += static_cast<int>(failed_.size());  // the house has its most rooms
  failed_.clear();
  phase_ = Phase::Done;
  HouseOrder o;
  o.kind = HouseOrder::Kind::Finished;
  return o;
}

HouseOrder HousePlanner::passExit() {
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(current_.room)];
  const Cell in = owner.toHouse.apply(current_.exit.inside);
  if (belief_.cell == in) return crossOrder();
  // The travel's frame: the robot's believed pose is its origin, as for an explorer's start.
  brickToHouse_ = network::RoomTransform::fromPose(belief_.cell, belief_.heading);
  const network::RoomTransform toLocal = brickToHouse_.inverse();
  Bounds box;
  const Cell target = toLocal.apply(legEnd(in, box));
  if (target == Cell{0, 0}) return failedPass();  // no leg gets any nearer
  HouseOrder o;
  o.kind = HouseOrder::Kind::Travel;
  o.target = target;
  // The known house around the leg, as much as the brick's grid holds.
  const Cell a = toLocal.apply(Cell{box.minX, box.minY}), b = toLocal.apply(Cell{box.maxX, box.maxY});
  const int minX = std::min(a.x, b.x), minY = std::min(a.y, b.y);
  // Only the known cells' box of it (and the robot's and the target's cells) goes to the brick.
  Bounds used{0, 0, 0, 0};
  const auto grow = [&](Cell c) {
    used =
        Bounds{std::min(used.minX, c.x), std::min(used.minY, c.y), std::max(used.maxX, c.x), std::max(used.maxY, c.y)};
  };
  grow(target);
  for (int y = minY; y < minY + box.height(); ++y) {
    for (int x = minX; x < minX + box.width(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (known_.at(brickToHouse_.apply(c)) != CellState::Unknown) grow(c);
    }
  }
  o.map = network::RoomMap(used.minX, used.minY, used.width(), used.height());
  for (int y = used.minY; y <= used.maxY; ++y) {
    for (int x = used.minX; x <= used.maxX; ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      o.map.set(c, known_.at(brickToHouse_.apply(c)));
    }
  }
  phase_ = Phase::Travel;
  log::debug("house", "travel from %d,%d (house) to exit inside %d,%d, leg target %d,%d (local), attempt %d",
             belief_.cell.x, belief_.cell.y, in.x, in.y, target.x, target.y, attempt_);
  return o;
}

Cell HousePlanner::legEnd(Cell inside, Bounds& box) const {
  // The shortest way from the robot to the exit over the known house (4-connected), walked back.
  const std::vector<int> dist = travelDistances(known_, belief_.cell);
  const auto at = [&](Cell c) {
    return known_.inside(c) ? dist[static_cast<size_t>((c.y - known_.minY()) * known_.width() + (c.x - known_.minX()))]
                            : -1;
  };
  std::vector<Cell> way{inside};
  while (at(way.back()) > 0) {
    const Cell c = way.back();
    Cell next = c;
    for (int d = 0; d < 4; ++d) {
      if (at(advance(c, static_cast<Dir>(d))) == at(c) - 1) next = advance(c, static_cast<Dir>(d));
    }
    if (next == c) break;
    way.push_back(next);
  }
  if (at(inside) < 0) way = {inside, belief_.cell};  // no known way: straight for the target
  std::reverse(way.begin(), way.end());
  // The longest start of the way whose box leaves a margin of the grid free around it (its walls).
  const int side = config_.gridCells, margin = 4;
  box = Bounds{belief_.cell.x, belief_.cell.y, belief_.cell.x, belief_.cell.y};
  size_t end = 0;
  for (size_t i = 1; i < way.size(); ++i) {
    Bounds grown = box;
    grown.minX = std::min(grown.minX, way[i].x);
    grown.minY = std::min(grown.minY, way[i].y);
    grown.maxX = std::max(grown.maxX, way[i].x);
    grown.maxY = std::max(grown.maxY, way[i].y);
    if (grown.width() > side - 2 * margin || grown.height() > side - 2 * margin) break;
    box = grown;
    end = i;
  }
  // The grid's box, centred on the leg.
  const int16_t padX = static_cast<int16_t>((side - box.width()) / 2),
                padY = static_cast<int16_t>((side - box.height()) / 2);
  box = Bounds{static_cast<int16_t>(box.minX - padX), static_cast<int16_t>(box.minY - padY),
               static_cast<int16_t>(box.minX - padX + side - 1), static_cast<int16_t>(box.minY - padY + side - 1)};
  return way[end];
}

HouseOrder HousePlanner::crossOrder() {
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(current_.room)];
  const network::RoomTransform toBrick = brickToHouse_.inverse() * owner.toHouse;
  HouseOrder o;
  o.kind = HouseOrder::Kind::Cross;
  o.exit = transformExit(current_.exit, toBrick);
  const network::RoomTransform houseToBrick = brickToHouse_.inverse();
  o.at = Pose{houseToBrick.apply(belief_.cell), houseToBrick.apply(belief_.heading)};
  phase_ = Phase::Cross;
  return o;
}

}  // namespace nxtmap::house
