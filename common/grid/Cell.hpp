#pragma once
#include <cstdint>

namespace nxtmap {

// A cell of a room map, in the explorer's frame: the start cell is (0,0), +y is the robot's
// initial forward direction, +x its initial right. Coordinates may be negative while mapping.
struct Cell {
  int16_t x = 0;
  int16_t y = 0;
  constexpr bool operator==(const Cell& o) const { return x == o.x && y == o.y; }
  constexpr bool operator!=(const Cell& o) const { return !(*this == o); }
};

// Absolute direction in the explorer's frame: North = +y (initial forward), East = +x.
enum class Dir : uint8_t { North = 0, East = 1, South = 2, West = 3 };

constexpr int16_t dx(Dir d) { return d == Dir::East ? 1 : (d == Dir::West ? -1 : 0); }
constexpr int16_t dy(Dir d) { return d == Dir::North ? 1 : (d == Dir::South ? -1 : 0); }
constexpr Dir opposite(Dir d) { return static_cast<Dir>((static_cast<uint8_t>(d) + 2) & 3); }
// Rotates clockwise by `quarters` quarter turns (negative = anticlockwise).
constexpr Dir rotate(Dir d, int quarters) { return static_cast<Dir>((static_cast<int>(d) + (quarters % 4) + 4) & 3); }
constexpr bool isVertical(Dir d) { return d == Dir::North || d == Dir::South; }
constexpr Cell advance(Cell c, Dir d, int16_t n = 1) {
  return Cell{static_cast<int16_t>(c.x + dx(d) * n), static_cast<int16_t>(c.y + dy(d) * n)};
}
constexpr Cell offset(Cell c, int dxCells, int dyCells) {
  return Cell{static_cast<int16_t>(c.x + dxCells), static_cast<int16_t>(c.y + dyCells)};
}

// The robot's four ultrasonic sensors, named relative to its body.
enum class Sensor : uint8_t { Front = 0, Right = 1, Back = 2, Left = 3 };
constexpr int kSensorCount = 4;

// The absolute direction a sensor looks at when the robot faces `heading`.
constexpr Dir sensorDir(Dir heading, Sensor s) { return rotate(heading, static_cast<int>(s)); }

// Inclusive rectangle of cells; empty when maxX < minX.
struct Bounds {
  int16_t minX = 0, minY = 0, maxX = -1, maxY = -1;
  constexpr bool empty() const { return maxX < minX || maxY < minY; }
  constexpr int16_t width() const { return empty() ? 0 : static_cast<int16_t>(maxX - minX + 1); }
  constexpr int16_t height() const { return empty() ? 0 : static_cast<int16_t>(maxY - minY + 1); }
  constexpr bool contains(Cell c) const { return c.x >= minX && c.x <= maxX && c.y >= minY && c.y <= maxY; }
};

}  // namespace nxtmap
