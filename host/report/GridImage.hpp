// GridImage: a PNG picture of any grid of cell states (free white, unknown grey, occupied black) with
// the robot's cell as a red square; what `export FILE.png` at the console writes.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "common/grid/CellState.hpp"
#include "host/report/MapImage.hpp"
#include "host/report/MapText.hpp"

namespace nxtmap::report {

struct GridImageOptions {
  int cellPx = 8;  // pixels per cell side (1..64)
};

// A width x height grid (col right, row down) at cellPx pixels a cell; the robot (its heading is not
// drawn) as a red square inset 1 px when given and inside the grid.
RgbImage renderGridImage(int width, int height, const std::function<CellState(int, int)>& cell,
                         const std::optional<RobotMark>& robot, const GridImageOptions& options = {});

// renderGridImage + writePng: false with `error` set when the file cannot be written.
bool writeGridPng(const std::string& path, int width, int height, const std::function<CellState(int, int)>& cell,
                  const std::optional<RobotMark>& robot, std::string& error, const GridImageOptions& options = {});

}  // namespace nxtmap::report
