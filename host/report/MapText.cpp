#include "host/report/MapText.hpp"

#include <algorithm>

#include "host/mapping/MappingRun.hpp"

namespace nxtmap::report {
namespace {
constexpr const char* kReset = "\x1b[0m";
constexpr const char* kUnknownColor = "\x1b[2m";      // dim
constexpr const char* kOccupiedColor = "\x1b[1;97m";  // bold bright white
constexpr const char* kRobotColor = "\x1b[1;91m";     // bold bright red
constexpr const char* kRulerColor = "\x1b[36m";       // cyan

int digits(int n) {
  int d = 1;
  while (n >= 10) {
    n /= 10;
    ++d;
  }
  return d;
}
}  // namespace

char cellGlyph(CellState s) {
  switch (s) {
    case CellState::Free: return ' ';
    case CellState::Occupied: return 'X';
    case CellState::Unknown: break;
  }
  return '~';
}

char headingGlyph(sim::Heading h) {
  switch (h) {
    case sim::Heading::N: return '^';
    case sim::Heading::E: return '>';
    case sim::Heading::S: return 'v';
    case sim::Heading::W: break;
  }
  return '<';
}

std::string renderMapText(int width, int height, const std::function<CellState(int, int)>& cell,
                          const std::optional<RobotMark>& robot, const MapTextOptions& options) {
  std::string out;
  if (width <= 0 || height <= 0) return out;
  const int labelWidth = options.rulers ? std::max(2, digits(height - 1)) : 0;
  const std::string margin = options.rulers ? std::string(static_cast<size_t>(labelWidth) + 1, ' ') : "";
  const bool color = options.color;

  auto ruler = [&](auto digitOf) {
    out += margin;
    out += ' ';
    if (color) out += kRulerColor;
    for (int col = 0; col < width; ++col) out += digitOf(col);
    if (color) out += kReset;
    out += '\n';
  };
  if (options.rulers) {
    for (int place = digits(width - 1) - 1; place >= 1; --place) {
      int scale = 1;
      for (int i = 0; i < place; ++i) scale *= 10;
      ruler([scale](int col) { return col >= scale ? static_cast<char>('0' + (col / scale) % 10) : ' '; });
    }
    ruler([](int col) { return static_cast<char>('0' + col % 10); });
  }
  const std::string border = margin + "+" + std::string(static_cast<size_t>(width), '-') + "+\n";
  out += border;
  for (int row = 0; row < height; ++row) {
    if (options.rulers) {
      const std::string label = std::to_string(row);
      out += std::string(static_cast<size_t>(labelWidth) - label.size(), ' ');
      if (color) out += kRulerColor;
      out += label;
      if (color) out += kReset;
      out += ' ';
    }
    out += '|';
    const char* active = nullptr;  // colour currently switched on
    auto setColor = [&](const char* want) {
      if (!color || want == active) return;
      if (active) out += kReset;
      if (want) out += want;
      active = want;
    };
    for (int col = 0; col < width; ++col) {
      if (robot && robot->col == col && robot->row == row) {
        setColor(kRobotColor);
        out += headingGlyph(robot->heading);
        continue;
      }
      const CellState s = cell(col, row);
      setColor(s == CellState::Occupied ? kOccupiedColor : s == CellState::Unknown ? kUnknownColor : nullptr);
      out += cellGlyph(s);
    }
    setColor(nullptr);
    out += "|\n";
  }
  out += border;
  return out;
}

std::string renderMapText(const mapping::MappingRun& run, const MapTextOptions& options) {
  RobotMark mark;
  run.believedCell(mark.col, mark.row);
  mark.heading = run.believedHeading();
  return renderMapText(
      run.world().width(), run.world().height(), [&run](int col, int row) { return run.belief(col, row); }, mark,
      options);
}

}  // namespace nxtmap::report
