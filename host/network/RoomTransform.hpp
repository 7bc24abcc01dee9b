// RoomTransform: the 2-D rigid transform from one room's frame to another's (usually the house
// frame), an Eigen isometry in cells. Rooms are mapped on the robot's axis grid, so the rotation
// is a whole number of quarter turns and the translation whole cells; cells map exactly.
#pragma once

#include <Eigen/Geometry>

#include "common/grid/Cell.hpp"

namespace nxtmap::network {

class RoomTransform {
 public:
  RoomTransform() : iso_(Eigen::Isometry2d::Identity()) {}
  // The frame whose origin is `origin` and whose +y points along `heading` (both in the target
  // frame): x' = origin + R(heading) x. quarterTurns = clockwise quarter turns of +y, 0..3.
  static RoomTransform fromPose(Cell origin, Dir heading);
  static RoomTransform fromParts(int x, int y, int quarterTurnsClockwise);

  Cell apply(Cell c) const;
  Dir apply(Dir d) const { return rotate(d, quarterTurns_); }
  RoomTransform inverse() const;
  RoomTransform operator*(const RoomTransform& o) const;  // (this * o)(c) = this(o(c))

  int x() const { return x_; }
  int y() const { return y_; }
  int quarterTurns() const { return quarterTurns_; }  // clockwise, 0..3
  const Eigen::Isometry2d& isometry() const { return iso_; }
  bool operator==(const RoomTransform& o) const { return x_ == o.x_ && y_ == o.y_ && quarterTurns_ == o.quarterTurns_; }

 private:
  Eigen::Isometry2d iso_;
  int x_ = 0, y_ = 0, quarterTurns_ = 0;
};

}  // namespace nxtmap::network
