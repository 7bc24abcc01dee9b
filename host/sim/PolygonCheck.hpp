// PolygonCheck: the plane geometry a world file's checks need (WorldFile): repeated points, area, a
// polygon that crosses itself, where a point lies against a polygon, segments that meet or cross.
// Units are the caller's (metres in WorldFile); `kTouchTolerance` is in those units: points closer than it
// to a side count as on the side, so a sofa set flush against a wall touches it rather than crossing it.
#pragma once

#include "host/sim/Scene.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace nxtmap::sim::polygon {

constexpr double kTouchTolerance = 1e-6;  // caller's unit (1 micrometre for metres)

// Indices of the points kept when consecutive repeats (closer than kTouchTolerance) are dropped; for a ring
// also a last point that repeats the first (a polygon written closed).
std::vector<size_t> distinctPoints(const std::vector<Vec2>& points, bool ring);

// Shoelace area: positive for counter-clockwise points in a y-up frame.
double signedArea(const std::vector<Vec2>& ring);

// True if every point lies on one straight line (within kTouchTolerance).
bool onOneLine(const std::vector<Vec2>& points);

// True if segments ab and cd share any point (within kTouchTolerance).
bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);
// True if ab and cd cross properly: each passes strictly from one side of the other to its other side.
bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// The first pair of sides (i < j; side i joins point i to point i+1, the last joins back to the first) that
// meet though they are not neighbours, or that are neighbours folding back along one line; nullopt if the
// ring (>= 3 points, without repeats) is a simple polygon.
std::optional<std::pair<size_t, size_t>> selfIntersection(const std::vector<Vec2>& ring);

enum class Place { Inside, On, Outside };
// Where p lies against the ring (even-odd rule; On within kTouchTolerance of a side).
Place locate(const std::vector<Vec2>& ring, const Vec2& p);

// A point strictly inside a simple ring, a little inward from the middle of its longest side (used to tell
// a polygon lying on top of another from one lying beside it).
Vec2 pointJustInside(const std::vector<Vec2>& ring);

}  // namespace nxtmap::sim::polygon
