#include "host/house/HouseScore.hpp"

#include "host/sim/WorldTruth.hpp"

#include <cctype>
#include <cmath>
#include <map>
#include <string>

namespace nxtmap::house {
namespace {
CellState beliefAt(const mapping::FrameTransform& f, const network::RoomMap& merged, int col, int row) {
  return merged.at(f.toExplorer(col, row));
}

// Calls f(col, row, d) for the world cells of plan room r, d their distance from its centre (cells): the box's
// cells; or, with a grid, every cell whose centre lies in the room's box on the plane.
template <class F>
void forRoomCells(const PlanRoom& r, const sim::World& world, const sim::GridFrame* grid, F f) {
  if (grid == nullptr) {
    const double cc = (r.minCol + r.maxCol) / 2.0, cr = (r.minRow + r.maxRow) / 2.0;
    for (int row = r.minRow; row <= r.maxRow; ++row)
      for (int col = r.minCol; col <= r.maxCol; ++col)
        if (world.inside(col, row)) f(col, row, std::hypot(col - cc, row - cr));
    return;
  }
  const double cx = (r.minXCm + r.maxXCm) / 2.0, cy = (r.minYCm + r.maxYCm) / 2.0;
  for (int row = 0; row < world.height(); ++row) {
    for (int col = 0; col < world.width(); ++col) {
      const sim::Vec2 p = grid->toPlane(sim::Vec2(col, row));
      if (r.containsPoint(p.x(), p.y())) f(col, row, std::hypot(p.x() - cx, p.y() - cy) / grid->cellCm);
    }
  }
}
}  // namespace

HouseInWorld houseInWorld(const HouseMapper& m) {
  return HouseInWorld{&m.network(),        &m.world(),          m.houseFrame(),
                      m.config().startCol, m.config().startRow, m.explorerConfig().geometry};
}

HouseScore scoreHouse(const HouseMapper& m) { return scoreHouse(houseInWorld(m)); }

PlanCoverage planCoverage(const HouseMapper& m, const HousePlan& plan, double minPct) {
  return planCoverage(houseInWorld(m), plan, minPct);
}

sim::Observability observabilityOf(const HouseInWorld& h) {
  return sim::computeObservability(*h.world, h.startCol, h.startRow, h.geometry.freeCells(), h.geometry.hitCells());
}

HouseScore scoreHouse(const HouseInWorld& h) { return scoreHouse(h, observabilityOf(h)); }

HouseScore scoreHouse(const HouseInWorld& h, const sim::Observability& obs) {
  const sim::World& world = *h.world;
  const network::RoomMap merged = h.network->merged();
  HouseScore s;
  s.rooms = static_cast<int>(h.network->rooms().size());
  s.gateways = static_cast<int>(h.network->gateways().size());
  for (int row = 0; row < world.height(); ++row) {
    for (int col = 0; col < world.width(); ++col) {
      const bool blocked = world.blocked(col, row);
      const CellState b = beliefAt(h.houseFrame, merged, col, row);
      const bool disagree = b != CellState::Unknown && ((b == CellState::Occupied) != blocked);
      if (obs.observable[static_cast<size_t>(row * world.width() + col)] == 0) {
        if (disagree) ++s.wrongElsewhere;
        continue;
      }
      ++s.observable;
      if (b == CellState::Unknown) {
        ++s.unknown;
      } else if (disagree) {
        ++s.wrong;
        if (b == CellState::Occupied) ++s.wallsOnFloor;
      } else {
        ++s.agree;
      }
    }
  }
  return s;
}

PlanCoverage planCoverage(const HouseInWorld& h, const HousePlan& plan, double minPct) {
  const sim::World& world = *h.world;
  const sim::Observability obs = sim::computeObservability(world, h.startCol, h.startRow, 1, 1);
  const network::RoomMap merged = h.network->merged();
  PlanCoverage c;
  c.planRooms = static_cast<int>(plan.rooms.size());
  for (const PlanRoom& r : plan.rooms) {
    int reachable = 0, mapped = 0;
    forRoomCells(r, world, h.grid, [&](int col, int row, double) {
      if (obs.reachable[static_cast<size_t>(row * world.width() + col)] == 0) return;
      ++reachable;
      if (beliefAt(h.houseFrame, merged, col, row) == CellState::Free) ++mapped;
    });
    if (reachable == 0) continue;
    ++c.reachable;
    if (100.0 * mapped >= minPct * reachable) ++c.covered;
  }
  return c;
}

PlanCoverage planCoverageOnGrid(const HouseMapper& m, const HousePlan& plan, double minPct) {
  HouseInWorld h = houseInWorld(m);
  h.grid = &m.robot().frame();
  return planCoverage(h, plan, minPct);
}

void labelRoomsFromPlan(HouseMapper& m, const HousePlan& plan, bool onRobotGrid) {
  auto& rooms = m.network().rooms();
  std::map<std::string, int> used;
  for (const PlanRoom& r : plan.rooms) {
    std::string base;
    for (const char ch : r.category) base += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (base.empty() || !std::isalpha(static_cast<unsigned char>(base[0]))) base = "room_" + base;
    // The free mapped cell nearest the box's centre, inside the box.
    int bestRoom = -1;
    Cell bestCell{};
    double bestD = 0.0;
    forRoomCells(r, m.world(), onRobotGrid ? &m.robot().frame() : nullptr, [&](int col, int row, double d) {
      if (bestRoom >= 0 && d >= bestD) return;
      const Cell h = m.houseFrame().toExplorer(col, row);
      for (size_t k = 0; k < rooms.size(); ++k) {
        const Cell local = rooms[k].toHouse.inverse().apply(h);
        if (!rooms[k].map.isFree(local)) continue;
        bestRoom = static_cast<int>(k);
        bestCell = local;
        bestD = d;
        break;
      }
    });
    if (bestRoom < 0) continue;
    const int n = ++used[base];
    const std::string name = n == 1 ? base : base + "_" + std::to_string(n);
    rooms[static_cast<size_t>(bestRoom)].labels[name] = bestCell;
  }
}

bool movePlanOntoGrid(HousePlan& plan, const sim::World& truth, const sim::GridFrame& frame) {
  const double cell = plan.world.resolutionM() * 100.0;
  if (std::fabs(truth.resolutionM() * 100.0 - cell) > 1e-9 || frame.headingDeg != 0.0) return false;
  const double dx = frame.originCm.x() / cell - 0.5, dy = frame.originCm.y() / cell - 0.5;
  if (std::fabs(dx - std::round(dx)) > 1e-6 || std::fabs(dy - std::round(dy)) > 1e-6) return false;
  const int shiftCol = -static_cast<int>(std::lround(dx)), shiftRow = -static_cast<int>(std::lround(dy));
  for (PlanRoom& r : plan.rooms) {
    r.minCol += shiftCol;
    r.maxCol += shiftCol;
    r.minRow += shiftRow;
    r.maxRow += shiftRow;
  }
  return true;
}

}  // namespace nxtmap::house
