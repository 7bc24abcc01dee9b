// A frontier explorer of the brick's geometry (20 cm cells, sensors 6 cm out, 7 cm .. 1.2 m trusted) against a
// scripted robot in a map drawn as text: moves and turns happen exactly, readings are the distance to the next
// blocked cell on the sensor's axis. Shared by the explorer's scenario tests.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"

namespace nxtmap {

// '#' blocked, anything else free; the first row is the top (highest y); 'S' is (0,0), where the robot starts
// facing +y. Outside the picture: blocked.
struct TextWorld {
  std::vector<std::string> rows;
  int sx = 0, sy = 0;  // the picture's column and row of 'S'
  explicit TextWorld(std::vector<std::string> r) : rows(std::move(r)) {
    for (int y = 0; y < static_cast<int>(rows.size()); ++y) {
      const size_t x = rows[static_cast<size_t>(y)].find('S');
      if (x != std::string::npos) sx = static_cast<int>(x), sy = y;
    }
  }
  bool blocked(Cell c) const {
    const int col = sx + c.x, row = sy - c.y;
    if (row < 0 || row >= static_cast<int>(rows.size())) return true;
    const std::string& line = rows[static_cast<size_t>(row)];
    return col < 0 || col >= static_cast<int>(line.size()) || line[static_cast<size_t>(col)] == '#';
  }
};

struct ScriptedRun {
  using Storage = ExplorerStorage<64, 64, 1024>;
  std::unique_ptr<Storage> storage = std::make_unique<Storage>();
  MapLayers map{storage->map.view(), Storage::kWidth(), Storage::kHeight()};
  TravelPlanner planner{storage->travel.view(), Storage::kWidth(), Storage::kHeight()};
  std::unique_ptr<FrontierExplorer> explorer;
  // The sensor: with blindCm > 0 (RangeGeometry::blindCm) nothing within range, and a face nearer than blindCm,
  // answer "no echo", as the NXT's does; with 0 nothing within range answers "too far" (the published model).
  int16_t blindCm = 0;
  bool bodySweeps = false;  // a turn stalls in a cell with a blocked neighbour (the body's corners reach into it)
  int turnsWithoutRoom = 0, turns = 0;
  bool stallFirstTurn = false;  // the first turn stalls (the pilot turned it back): Event::turnBlocked()
  int grazes = 0;  // this many moves back into a cell the robot stood in are blocked (a body grazing a wall)
  bool stalled = false;
  Cell stalledAt{};
  int turnsAtStalled = 0;
  std::vector<Cell> turnedAt;  // where each turn that was made began

  RangeReading read(const TextWorld& world, const Pose& pose, Sensor s) const {
    const Dir d = sensorDir(pose.heading, s);
    int16_t k = 1;
    while (k <= 8 && !world.blocked(advance(pose.cell, d, k))) ++k;
    RangeReading r;
    r.samples = 1;
    const int16_t cm = static_cast<int16_t>(k * 20 - 10 - 6);  // to the near face, from the sensor
    const bool far = k > 8 || cm > 120, blind = cm < blindCm;
    r.status = !far && !blind ? RangeStatus::Good : (blindCm > 0 ? RangeStatus::NoEcho : RangeStatus::TooFar);
    r.cm = far || blind ? 0 : cm;
    return r;
  }

  Event answer(const TextWorld& world, Pose& pose, const Action& a) {
    if (a.kind == Action::Kind::Read) return Event::range(a.sensor, read(world, pose, a.sensor));
    bool cornered = false;
    for (int d = 0; d < 4; ++d) cornered = cornered || world.blocked(advance(pose.cell, static_cast<Dir>(d)));
    if (a.kind == Action::Kind::Turn && ((stallFirstTurn && !stalled) || (bodySweeps && cornered))) {
      stalled = true;
      stalledAt = pose.cell;
      return Event::turnBlocked();
    }
    if (a.kind == Action::Kind::Turn) {
      ++turns;
      turnsAtStalled += stalled && pose.cell == stalledAt ? 1 : 0;
      turnsWithoutRoom += TravelPlanner::roomToTurn(map.grid(), pose.cell) ? 0 : 1;
      turnedAt.push_back(pose.cell);
      pose.heading = rotate(pose.heading, a.amount / 2);
      return Event::turned(a.amount);
    }
    if (a.kind == Action::Kind::Move) {
      const Dir d = a.amount > 0 ? pose.heading : opposite(pose.heading);
      if (world.blocked(advance(pose.cell, d))) return Event::blocked();
      if (grazes > 0 && map.evidence(advance(pose.cell, d)) == -7) {
        --grazes;
        return Event::blocked();
      }
      pose.cell = advance(pose.cell, d);
      return Event::moved(a.amount);
    }
    return Event::thought();
  }

  void go(const TextWorld& world) {
    ExplorerConfig c;
    c.geometry.cellCm = 20;
    c.geometry.minCm = 7;
    c.geometry.maxCm = 120;
    c.geometry.mountCm = 6;
    c.geometry.blindCm = blindCm;
    c.turnNeedsRoom = true;
    explorer = std::make_unique<FrontierExplorer>(map, planner, c);
    Pose pose{};
    Action a = explorer->step(Event::startAt(pose));
    for (int i = 0; i < 20000 && !explorer->finished(); ++i) a = explorer->step(answer(world, pose, a));
  }
};

}  // namespace nxtmap
