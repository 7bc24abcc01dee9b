// MapText: the method's console display of a map (section 7: free " ", unknown "~", occupied "X"),
// with the robot drawn as ^ > v < by its believed heading, a frame and column/row rulers.
#pragma once
#include <functional>
#include <optional>
#include <string>

#include "common/grid/CellState.hpp"
#include "host/sim/Heading.hpp"

namespace nxtmap::mapping {
class MappingRun;
}

namespace nxtmap::report {

struct MapTextOptions {
  bool color = false;  // ANSI colours (only when writing to a terminal)
  bool rulers = true;  // column numbers above, row numbers on the left
};

struct RobotMark {
  int col = 0, row = 0;
  sim::Heading heading = sim::Heading::N;
};

// The glyph of a cell state: ' ', '~', 'X'.
char cellGlyph(CellState s);
// The robot glyph: '^' N, '>' E, 'v' S, '<' W.
char headingGlyph(sim::Heading h);

// Renders a width x height grid (col right, row down), one character per cell; every line ends
// with '\n'. The robot is drawn when given and inside the grid.
std::string renderMapText(int width, int height, const std::function<CellState(int, int)>& cell,
                          const std::optional<RobotMark>& robot, const MapTextOptions& options = {});

// The belief of a run over its world's extent, with the believed robot cell and heading.
std::string renderMapText(const mapping::MappingRun& run, const MapTextOptions& options = {});

}  // namespace nxtmap::report
