#include "host/house/HouseMapper.hpp"

#include "common/motion/Pilot.hpp"
#include "common/explore/GoToExplorer.hpp"
#include "host/house/OpeningSearch.hpp"
#include "host/house/RoomRegistration.hpp"
#include "host/house/RoomSplit.hpp"
#include "host/house/StandingScan.hpp"
#include "host/house/TravelDistances.hpp"
#include "host/mapping/SimDrive.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <memory>

namespace nxtmap::house {
namespace {
ExplorerConfig explorerConfigFor(const sim::World& world, const HouseConfig& c, int mountCm) {
  ExplorerConfig e;
  e.geometry = mapping::sonarGeometryFor(world, c.minRangeM, c.rangeM, c.noise.sonar.coneHalfAngleDeg, mountCm);
  return e;
}

sim::RobotPlacement placementFor(const sim::Site& site, const HouseConfig& c) {
  return sim::placeRobot(site, sim::PlacementRequest{c.robot, c.startPose, c.startCol, c.startRow, c.heading,
                                                     c.startJitterDeg, c.seed, 0.0});
}

// The configuration with the start cell on the robot's grid and the ranges the robot trusts.
HouseConfig placedConfig(const sim::RobotPlacement& placed, HouseConfig c) {
  c.startCol = placed.grid.startCol;
  c.startRow = placed.grid.startRow;
  c.heading = placed.heading;
  if (c.robot) {
    c.minRangeM = c.robot->minRangeM;
    c.rangeM = c.robot->rangeM;
  }
  return c;
}

}  // namespace

HouseMapper::HouseMapper(const sim::World& world, const HouseConfig& config)
    : HouseMapper(sim::siteFromRaster(world), config) {}

HouseMapper::HouseMapper(const sim::Site& site, const HouseConfig& config)
    : HouseMapper(placementFor(site, config), config) {}

HouseMapper::HouseMapper(sim::RobotPlacement placed, const HouseConfig& config)
    : world_(std::move(placed.truth)),
      config_(placedConfig(placed, config)),
      explorerConfig_(explorerConfigFor(world_, config_, placed.robot.mountCm)),
      frame_(config_.startCol, config_.startRow, config_.heading),
      robot_(placed.scene, placed.robot, placed.grid.frame, placed.start.cm, placed.start.headingDeg, config_.noise,
             config_.seed, config_.sensorReachCm) {}

void HouseMapper::mapRoom(const std::vector<Cell>& entranceHouse, int fromRoom, const RoomExit* via) {
  network::RoomTransform toHouse = network::RoomTransform::fromPose(belief_.cell, belief_.heading);
  const network::RoomTransform toRoom = toHouse.inverse();
  std::vector<Cell> entrance;
  for (const Cell c : entranceHouse) entrance.push_back(toRoom.apply(c));
  RoomRun run(robot_, explorerConfig_, config_.strategy, config_.doorways, entrance, pilotConfig(), config_.roomLimits);
  run.runToEnd();
  headingVariance_ = run.handOverHeadingVariance();
  if (std::getenv("NXTMAP_HOUSE_DEBUG")) {
    std::fprintf(stderr, "room %zu: end %d, pose %d,%d, exits %zu, ignored %d\n", network_.rooms().size(),
                 static_cast<int>(run.end()), run.pose().cell.x, run.pose().cell.y, run.exits().size(),
                 run.ignoredDoorways());
    for (const RoomExit& e : run.exits())
      std::fprintf(stderr, "  exit inside %d,%d out %d depth %d cells %zu\n", e.inside.x, e.inside.y,
                   static_cast<int>(e.outward), e.depth, e.cells.size());
  }
  // The new room's frame came from the believed pose at its entrance; what it saw through the doorway
  // and of the walls it shares with the rooms already mapped re-registers it (and the belief with it).
  if (fromRoom >= 0 && config_.registerCells > 0) {
    const RoomRegistration r = registerRoom(run.fullMap(), toHouse, network_.merged(), config_.registerCells);
    if (std::getenv("NXTMAP_HOUSE_DEBUG") && r.shifted())
      std::fprintf(stderr, "  registered by %d,%d (score %d -> %d)\n", r.dx, r.dy, r.scoreBefore, r.scoreAfter);
    toHouse = r.toHouse;
  }
  // The start room: the start readings against the finished map (see StartAnchor).
  if (fromRoom < 0 && config_.anchorStart) toHouse = anchoredStart(run, toHouse);
  const Counters& c = run.counters();
  counters_.explore.sensorRequests += c.sensorRequests;
  counters_.explore.rawSamples += c.rawSamples;
  counters_.explore.cellsMoved += c.cellsMoved;
  counters_.explore.turnEighths += c.turnEighths;
  counters_.explore.blockedMoves += c.blockedMoves;
  counters_.explore.correctionMrad += c.correctionMrad;

  // An open area larger than the maximum becomes several rooms (parts share the room's frame).
  const RoomParts parts = splitRoom(run.roomMap(), run.interpretation());
  const int first = static_cast<int>(network_.rooms().size());
  for (const network::RoomMap& part : parts.maps) {
    network::RoomNode node;
    node.name = "room" + std::to_string(network_.rooms().size());
    node.map = part;
    node.toHouse = toHouse;
    network_.addRoom(std::move(node));
  }
  for (const RoomParts::Cut& cut : parts.cuts) {
    network_.addGateway(network::Gateway{first + cut.partA, first + cut.partB, cut.cells, cut.cells});
  }
  const auto partOf = [&](Cell at) { return first + std::max(0, parts.partOf(at)); };
  if (fromRoom >= 0 && via != nullptr && !entrance.empty()) {
    network::Gateway g;
    g.roomA = fromRoom;
    g.roomB = partOf(entrance[entrance.size() / 2]);
    g.cellsA = via->cells;
    g.cellsB = entrance;
    network_.addGateway(std::move(g));
  }
  for (const RoomExit& e : run.exits()) pending_.push_back(Pending{partOf(e.inside), e});
  network::RoomNode seen;
  seen.name = "run " + std::to_string(seen_.size());
  seen.map = run.fullMap();
  seen.toHouse = toHouse;
  seen_.push_back(std::move(seen));
  exitsFound_ += static_cast<int>(run.exits().size());
  belief_.cell = toHouse.apply(run.pose().cell);
  belief_.heading = toHouse.apply(run.pose().heading);
  debugBelief("after room");
}

network::RoomTransform HouseMapper::anchoredStart(const RoomRun& run, const network::RoomTransform& toHouse) {
  const RangeGeometry& g = explorerConfig_.geometry;
  RangeGeometry reach = g;
  reach.maxCm = static_cast<int16_t>(std::max<int>(g.maxCm, pilotConfig().poseRangeCm));
  std::vector<AnchorReading> anchor;
  for (const RoomRun::StartReading& sr : run.startReadings()) {
    // Every echo the pilot would match against a known wall (out to its pose range, beyond the
    // mapping range); one too near lies at the adjacent cell's face.
    const RangeReading& r = sr.reading;
    if (r.status == RangeStatus::TooNear) anchor.push_back(AnchorReading{sr.dir, g.cellCm * 5});
    if (r.status == RangeStatus::Good || (r.status == RangeStatus::TooFar && r.cm > 0 && r.cm <= reach.maxCm))
      anchor.push_back(AnchorReading{sr.dir, (r.cm + g.mountCm) * 10});
  }
  AnchorGeometry ag;
  ag.cellMm = g.cellCm * 10;
  ag.reachCells = reach.hitCells();
  ag.wideFromMm = (g.sureCm > 0 ? g.sureCm : g.maxCm) * 10;
  const Cell s = startAnchorShift(run.fullMap(), Cell{0, 0}, anchor, ag);
  if (s.x == 0 && s.y == 0) return toHouse;
  // Room cell s is where the robot started: it goes where the start is in the house.
  const Cell moved = toHouse.apply(s), start = toHouse.apply(Cell{0, 0});
  startShift_ = s;
  if (std::getenv("NXTMAP_HOUSE_DEBUG")) std::fprintf(stderr, "  start anchor: frame moved by %d,%d\n", s.x, s.y);
  return network::RoomTransform::fromParts(toHouse.x() - (moved.x - start.x), toHouse.y() - (moved.y - start.y),
                                           toHouse.quarterTurns());
}

network::RoomMap HouseMapper::knownForTravel() const {
  network::HouseNetwork all = network_;
  for (const network::RoomNode& n : seen_) all.addRoom(n);
  return all.merged();
}

void HouseMapper::debugBelief(const char* when) const {
  if (!std::getenv("NXTMAP_HOUSE_DEBUG")) return;
  int col = 0, row = 0;
  frame_.toWorld(belief_.cell, col, row);
  std::fprintf(stderr, "  %s: believed world %d,%d heading %d; true %.1f,%.1f heading %.1f deg\n", when, col, row,
               static_cast<int>(frame_.toWorld(belief_.heading)) * 90, robot_.xCm() / 10.0, robot_.yCm() / 10.0,
               robot_.headingDeg());
}

bool HouseMapper::leadsToMappedRoom(const Pending& p) {
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(p.room)];
  const Cell inside = owner.toHouse.apply(p.exit.inside);
  const Dir out = owner.toHouse.apply(p.exit.outward);
  const auto& rooms = network_.rooms();
  for (int k = 1; k <= 2; ++k) {
    const Cell beyond = advance(inside, out, static_cast<int16_t>(p.exit.depth + k));
    for (size_t j = 0; j < rooms.size(); ++j) {
      if (static_cast<int>(j) == p.room) continue;
      const network::RoomTransform toJ = rooms[j].toHouse.inverse();
      if (!rooms[j].map.isFree(toJ.apply(beyond))) continue;
      // A gateway to a mapped room; skip it when that doorway is already a gateway of the two.
      std::vector<Cell> house, inJ;
      for (const Cell c : p.exit.cells) {
        house.push_back(owner.toHouse.apply(c));
        inJ.push_back(toJ.apply(house.back()));
      }
      // The same doorway seen from the other room may be found a cell wider or shifted.
      bool known = false;
      for (const int gi : network_.gatewaysBetween(p.room, static_cast<int>(j))) {
        const network::Gateway& g = network_.gateways()[static_cast<size_t>(gi)];
        for (const auto& [room, cells] : {std::make_pair(g.roomA, &g.cellsA), std::make_pair(g.roomB, &g.cellsB)}) {
          const network::RoomNode& a = rooms[static_cast<size_t>(room)];
          for (const Cell gc : *cells) {
            const Cell h = a.toHouse.apply(gc);
            for (const Cell hc : house) known = known || (std::abs(h.x - hc.x) + std::abs(h.y - hc.y) <= 2);
          }
        }
      }
      if (!known) {
        network::Gateway g;
        g.roomA = p.room;
        g.roomB = static_cast<int>(j);
        g.cellsA = p.exit.cells;
        g.cellsB = inJ;
        network_.addGateway(std::move(g));
      }
      return true;
    }
  }
  return false;
}

PilotConfig HouseMapper::pilotConfig() const {
  PilotConfig pc;
  pc.correct = config_.poseCorrection;
  pc.startHeadingVarianceMrad2 = config_.poseCorrection ? headingVariance_ : 0;
  return pc;
}

bool HouseMapper::step(Dir d) {
  if (belief_.heading != d) {
    int eighths = 4;
    if (rotate(belief_.heading, 1) == d) eighths = 2;
    if (rotate(belief_.heading, -1) == d) eighths = -2;
    robot_.turn(eighths);
    const int64_t sigma = static_cast<int64_t>(pilotConfig().noise.turnMradPerQuarter) * std::abs(eighths) / 2;
    headingVariance_ += sigma * sigma;  // a dead-reckoned turn: nothing measures its error
    counters_.travel.turnEighths += static_cast<uint32_t>(std::abs(eighths));
    belief_.heading = d;
  }
  const sim::MoveResult r = robot_.move(1);
  if (r.blocked) {
    ++counters_.travel.blockedMoves;
    return false;
  }
  ++counters_.travel.cellsMoved;
  belief_.cell = advance(belief_.cell, d);
  return true;
}

bool HouseMapper::travelTo(Cell target, const network::RoomMap& known) {
  if (belief_.cell == target) return true;
  // The travel's frame: the robot's believed pose is its origin, as for an explorer's start.
  const network::RoomTransform toHouse = network::RoomTransform::fromPose(belief_.cell, belief_.heading);
  const network::RoomTransform toLocal = toHouse.inverse();
  auto storage = std::make_unique<RoomRun::Storage>();
  MapLayers map(storage->map.view(), RoomRun::Storage::kWidth(), RoomRun::Storage::kHeight());
  TravelPlanner planner(storage->travel.view(), RoomRun::Storage::kWidth(), RoomRun::Storage::kHeight());
  for (int y = known.minY(); y <= known.maxY(); ++y) {
    for (int x = known.minX(); x <= known.maxX(); ++x) {
      const Cell h{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      const CellState s = known.at(h);
      if (s == CellState::Unknown) continue;
      const Cell c = toLocal.apply(h);
      if (!map.grid().fits(c)) continue;
      (void)(s == CellState::Free ? map.observeFree(c) : map.observeOccupied(c));
    }
  }
  GoToExplorer go(map, planner, explorerConfig_, toLocal.apply(target));
  Pilot pilot(go, pilotConfig());
  DriveAction a = pilot.step(DriveEvent::start());
  while (!pilot.finished()) a = pilot.step(mapping::carryOutOnRobot(robot_, a, explorerConfig_.geometry));
  const DriveAction level = pilot.levelling();  // on the axis for what follows (dead-reckoned steps, a new room)
  headingVariance_ = pilot.handOverHeadingVariance();
  if (level.kind == DriveAction::Kind::Rotate) (void)mapping::carryOutOnRobot(robot_, level, explorerConfig_.geometry);
  const Counters c = pilot.counters();
  counters_.travel.sensorRequests += c.sensorRequests;
  counters_.travel.rawSamples += c.rawSamples;
  counters_.travel.cellsMoved += c.cellsMoved;
  counters_.travel.turnEighths += c.turnEighths;
  counters_.travel.blockedMoves += c.blockedMoves;
  counters_.travel.correctionMrad += c.correctionMrad;
  belief_.cell = toHouse.apply(go.pose().cell);
  belief_.heading = toHouse.apply(go.pose().heading);
  if (!go.arrived()) ++counters_.travelBlocked;
  debugBelief("after travel");
  return go.arrived();
}

int HouseMapper::run() {
  belief_ = Pose{};
  headingVariance_ = 0;
  mapRoom({}, -1, nullptr);
  do {
    mapPendingExits();
  } while (queueOpening());
  return static_cast<int>(network_.rooms().size());
}

void HouseMapper::mapPendingExits() {
  bool relocalisedHere = false;  // since the robot last moved
  while (!pending_.empty() && static_cast<int>(network_.rooms().size()) < config_.maxRooms) {
    // Exits into rooms already mapped become gateways without a run.
    pending_.erase(
        std::remove_if(pending_.begin(), pending_.end(), [&](const Pending& p) { return leadsToMappedRoom(p); }),
        pending_.end());
    if (pending_.empty()) break;
    const network::RoomMap known = knownForTravel();
    const std::vector<int> dist = travelDistances(known, belief_.cell);
    size_t best = pending_.size();
    int bestDist = std::numeric_limits<int>::max();
    for (size_t i = 0; i < pending_.size(); ++i) {
      const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(pending_[i].room)];
      const Cell in = owner.toHouse.apply(pending_[i].exit.inside);
      if (!known.inside(in)) continue;
      const int d =
          dist.empty() ? -1 : dist[static_cast<size_t>((in.y - known.minY()) * known.width() + (in.x - known.minX()))];
      if (d >= 0 && d < bestDist) {
        bestDist = d;
        best = i;
      }
    }
    // Nothing reachable from the believed cell: the robot may be lost in a pocket of the map.
    if (best == pending_.size() && !relocalisedHere && relocalise(known, nullptr)) {
      relocalisedHere = true;
      continue;
    }
    if (best == pending_.size()) {  // nothing left that can be reached
      if (std::getenv("NXTMAP_HOUSE_DEBUG")) std::fprintf(stderr, "no reachable exit among %zu\n", pending_.size());
      exitsUnreached_ += static_cast<int>(pending_.size());
      pending_.clear();
      break;
    }
    const Pending p = pending_[best];
    pending_.erase(pending_.begin() + static_cast<long>(best));
    const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(p.room)];
    const Cell in = owner.toHouse.apply(p.exit.inside);
    const Dir out = owner.toHouse.apply(p.exit.outward);
    bool through = passExit(in, out, p.exit.depth, known);
    // Blocked by a wall the map does not have there: the robot is lost by a cell or more.
    const Dir facing = belief_.heading;
    if (!through && relocalise(known, &facing)) through = passExit(in, out, p.exit.depth, known);
    relocalisedHere = false;
    if (!through) {
      if (std::getenv("NXTMAP_HOUSE_DEBUG"))
        std::fprintf(stderr, "exit not passed: at %d,%d\n", belief_.cell.x, belief_.cell.y);
      ++exitsUnreached_;
      continue;
    }
    std::vector<Cell> entranceHouse;
    for (const Cell c : p.exit.cells) entranceHouse.push_back(owner.toHouse.apply(c));
    const int from = p.room;
    const RoomExit via = p.exit;
    mapRoom(entranceHouse, from, &via);
    relocalisedHere = false;
  }
}

bool HouseMapper::passExit(Cell inside, Dir outward, int depth, const network::RoomMap& known) {
  bool through = travelTo(inside, known);
  for (int k = 0; through && k <= depth; ++k) through = step(outward);
  return through;
}

bool HouseMapper::relocalise(const network::RoomMap& known, const Dir* blocked) {
  if (config_.relocaliseCells <= 0) return false;
  const RangeGeometry& g = explorerConfig_.geometry;
  const int reachCm = std::max<int>(g.maxCm, pilotConfig().poseRangeCm);
  std::vector<StandingReading> readings;
  for (int i = 0; i < kSensorCount; ++i) {
    const Sensor s = static_cast<Sensor>(i);
    const DriveEvent e = mapping::carryOutOnRobot(robot_, DriveAction::read(s), g);
    ++counters_.travel.sensorRequests;
    counters_.travel.rawSamples += e.reading.samples;
    StandingReading r;
    r.dir = sensorDir(belief_.heading, s);
    const RangeReading& rr = e.reading;
    if (rr.status == RangeStatus::Inconsistent) continue;  // says nothing
    r.echo = rr.status == RangeStatus::Good || rr.status == RangeStatus::TooNear ||
             (rr.status == RangeStatus::TooFar && rr.cm > 0 && rr.cm <= reachCm);
    r.cm = rr.status == RangeStatus::TooNear ? g.minCm : rr.cm;
    readings.push_back(r);
  }
  const Cell shift = bestStandingShift(known, belief_.cell, readings, g, reachCm, blocked, config_.relocaliseCells);
  if (shift.x == 0 && shift.y == 0) return false;
  belief_.cell = Cell{static_cast<int16_t>(belief_.cell.x + shift.x), static_cast<int16_t>(belief_.cell.y + shift.y)};
  ++relocalisations_;
  if (std::getenv("NXTMAP_HOUSE_DEBUG")) std::fprintf(stderr, "relocalised by %d,%d\n", shift.x, shift.y);
  debugBelief("relocalised");
  return true;
}

bool HouseMapper::queueOpening() {
  // No exit left: space the exits missed (a doorway never recognised) is explored through the
  // widest opening onto it, as if it were an exit.
  if (static_cast<int>(network_.rooms().size()) >= config_.maxRooms ||
      static_cast<int>(openingsTried_.size()) >= config_.maxOpenings)
    return false;
  const std::optional<Opening> o = findOpening(network_, knownForTravel(), openingsTried_);
  if (!o) return false;
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(o->room)];
  openingsTried_.push_back(owner.toHouse.apply(o->inside));
  if (std::getenv("NXTMAP_HOUSE_DEBUG"))
    std::fprintf(stderr, "opening of room %d, %zu cells wide, at %d,%d\n", o->room, o->cells.size(),
                 openingsTried_.back().x, openingsTried_.back().y);
  pending_.push_back(Pending{o->room, RoomExit{o->cells, o->inside, o->outward, 1}});
  return true;
}

}  // namespace nxtmap::house
