// The explorer of a body that turns only where the four cells around it are known free
// (ExplorerConfig::turnNeedsRoom), against a scripted robot in a map drawn as text: when nothing is left within
// reach by that rule, it tries once more turning anywhere (the pilot turns a turn that meets something back);
// where a turn with room is at hand, the rule holds.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"

namespace nxtmap {
namespace {

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
  int turnsWithoutRoom = 0, turns = 0;
  bool stallFirstTurn = false;  // the first turn stalls (the pilot turned it back): Event::turnBlocked()
  bool stalled = false;
  Cell stalledAt{};
  int turnsAtStalled = 0;

  // The brick's geometry: 20 cm cells, sensors 6 cm out, 7 cm .. 1.2 m trusted (6 cells).
  void go(const TextWorld& world) {
    ExplorerConfig c;
    c.geometry.cellCm = 20;
    c.geometry.minCm = 7;
    c.geometry.maxCm = 120;
    c.geometry.mountCm = 6;
    c.turnNeedsRoom = true;
    explorer = std::make_unique<FrontierExplorer>(map, planner, c);
    Pose pose{};
    Action a = explorer->step(Event::startAt(pose));
    for (int i = 0; i < 5000 && !explorer->finished(); ++i) {
      Event e = Event::thought();
      if (a.kind == Action::Kind::Read) {
        const Dir d = sensorDir(pose.heading, a.sensor);
        int16_t k = 1;
        while (k <= 8 && !world.blocked(advance(pose.cell, d, k))) ++k;
        RangeReading r;
        r.samples = 1;
        const int16_t cm = static_cast<int16_t>(k * 20 - 10 - 6);  // to the near face, from the sensor
        r.status = k > 8 || cm > 120 ? RangeStatus::TooFar : RangeStatus::Good;
        r.cm = r.status == RangeStatus::Good ? cm : 0;
        e = Event::range(a.sensor, r);
      } else if (a.kind == Action::Kind::Turn && stallFirstTurn && !stalled) {
        stalled = true;
        stalledAt = pose.cell;
        e = Event::turnBlocked();
      } else if (a.kind == Action::Kind::Turn) {
        ++turns;
        turnsAtStalled += stalled && pose.cell == stalledAt ? 1 : 0;
        turnsWithoutRoom += TravelPlanner::roomToTurn(map.grid(), pose.cell) ? 0 : 1;
        pose.heading = rotate(pose.heading, a.amount / 2);
        e = Event::turned(a.amount);
      } else if (a.kind == Action::Kind::Move) {
        const Dir d = a.amount > 0 ? pose.heading : opposite(pose.heading);
        if (world.blocked(advance(pose.cell, d))) {
          e = Event::blocked();
        } else {
          pose.cell = advance(pose.cell, d);
          e = Event::moved(a.amount);
        }
      }
      a = explorer->step(e);
    }
  }
};

TEST(RoomWaiver, WithNothingLeftInReachTurningWithRoomTheRobotTurnsWhereItMust) {
  // A corridor one cell wide opening onto a row one cell deep and 16 long: no cell has four free neighbours,
  // and the row's far ends lie beyond the sensors' 6 cells from the corridor's end.
  const TextWorld world({"##################", "#................#", "########.#########", "########.#########",
                         "########S#########", "##################"});
  ScriptedRun run;
  run.go(world);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turnsWithoutRoom, 1);
  // Both ends of the row are mapped: its end walls (8 and 9 cells from the corridor) are known.
  EXPECT_EQ(run.map.at(Cell{-8, 3}), CellState::Occupied);
  EXPECT_EQ(run.map.at(Cell{9, 3}), CellState::Occupied);
}

TEST(RoomWaiver, WhereATurnWithRoomIsAtHandTheRuleHolds) {
  // An open room: every turn can be made where the four cells around are free.
  const TextWorld world(
      {"##########", "#........#", "#........#", "#........#", "#...S....#", "#........#", "#........#", "##########"});
  ScriptedRun run;
  run.go(world);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turns, 1);
  EXPECT_EQ(run.turnsWithoutRoom, 0);
}

TEST(RoomWaiver, NoTurnIsTriedAgainWhereOneStalled) {
  const TextWorld world(
      {"##########", "#........#", "#........#", "#........#", "#...S....#", "#........#", "#........#", "##########"});
  ScriptedRun run;
  run.stallFirstTurn = true;
  run.go(world);
  ASSERT_TRUE(run.stalled);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turns, 1);
  EXPECT_EQ(run.turnsAtStalled, 0);
  EXPECT_EQ(run.explorer->counters().blockedMoves, 1u);
}

}  // namespace
}  // namespace nxtmap
