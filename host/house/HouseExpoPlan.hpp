// HouseExpoPlan: a HouseExpo floor plan (TeaganLi/HouseExpo JSON) rasterised into a simulator world.
// The JSON holds `verts`, one outline polygon in metres (interior walls are thin notches of it),
// `room_category` {name: [[x1, y1, x2, y2], ...]} room boxes in metres, `room_num`, `id`, `bbox`.
// Rasterising: a cell whose centre lies inside the polygon (even-odd rule) is free, every other
// cell is wall; one ring of wall cells surrounds the bounding box. World rows grow downwards,
// y in metres grows upwards: row 0 holds the plan's highest y. Beside the raster, the plan keeps its
// outline exactly as given (sim::Scene, no snapping) in the raster's plane, so the two stay in register.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/sim/Scene.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::house {

// A room box of the plan, in world cells (inclusive; col right, row down) and in the plan's plane (cm, y down,
// the scene's: HousePlan::scene), where any grid laid on the plane can place it.
struct PlanRoom {
  std::string category;  // e.g. "Kitchen"
  int minCol = 0, minRow = 0, maxCol = 0, maxRow = 0;
  double minXCm = 0, minYCm = 0, maxXCm = 0, maxYCm = 0;
  bool contains(int col, int row) const { return col >= minCol && col <= maxCol && row >= minRow && row <= maxRow; }
  bool containsPoint(double xCm, double yCm) const {
    return xCm >= minXCm && xCm <= maxXCm && yCm >= minYCm && yCm <= maxYCm;
  }
};

struct HousePlan {
  std::string id;
  int roomNum = 0;              // the plan's own room count
  std::vector<PlanRoom> rooms;  // one per room box
  sim::World world;
  // The metres of the world's lower-left corner (col 0's left edge, the last row's bottom edge).
  double originXM = 0.0, originYM = 0.0;
  // The outline polygon exactly as given, one Hard ring, finished; in the world's plane (cm, y down):
  // x = (xM - originXM) * 100, y = (originYM + height * resolutionM - yM) * 100, so cell (col, row) spans
  // x col * cellCm .. (col + 1) * cellCm and y row * cellCm .. (row + 1) * cellCm. Shared, never null
  // in a loaded plan.
  std::shared_ptr<const sim::Scene> scene;
};

struct HousePlanLoad {
  std::optional<HousePlan> plan;
  std::string error;  // names the file and the problem when plan is empty
};

// The bounds of an accepted plan. HouseExpo's plans have from a dozen to a few hundred outline points
// and are a few tens of metres across at most. Rasterising takes O(rows x points + cells): at most
// 4096 x 4096 edge tests and cells, well under a second.
constexpr size_t kMaxPlanFileBytes = 1024 * 1024;  // the JSON file
constexpr size_t kMaxPlanPoints = 4096;            // outline points in `verts`
constexpr size_t kMaxPlanRoomBoxes = 256;          // boxes in `room_category`, all categories; also room_num's bound
constexpr double kMaxPlanCoordM = 1000.0;          // every coordinate within -1000..1000 m
constexpr double kMaxPlanSideM = 100.0;            // the outline's width and height, metres
// The rasterised world is at most sim::World::kMaxSide cells a side as well (4096: 41 m at 0.01 m).

// Reads and rasterises a HouseExpo JSON file; resolution in metres per cell (0.01 .. 1). The file must be
// a regular file of at most kMaxPlanFileBytes; every number must be finite and within the bounds above;
// a room box must overlap the outline's bounding box (it is clipped to the world); a room category is
// 1..48 of [A-Za-z0-9_-] (it names a label); `id`, when given, 1..128 printable ASCII characters.
HousePlanLoad loadHouseExpo(const std::string& path, double resolutionM = 0.10);
// The same from the JSON text; `name` is used in messages and as the world's name.
HousePlanLoad parseHouseExpo(const std::string& json, const std::string& name, double resolutionM = 0.10);

// A good start for a run: among the free cells at least 4 cells from any wall (or as far as any
// gets), the one nearest the first room box's centre. False when the plan has no free cell.
bool defaultStart(const HousePlan& plan, int& col, int& row);

}  // namespace nxtmap::house
