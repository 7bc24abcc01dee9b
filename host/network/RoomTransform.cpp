#include "host/network/RoomTransform.hpp"

#include <cmath>

namespace nxtmap::network {

RoomTransform RoomTransform::fromParts(int x, int y, int quarterTurnsClockwise) {
  RoomTransform t;
  t.x_ = x;
  t.y_ = y;
  t.quarterTurns_ = ((quarterTurnsClockwise % 4) + 4) % 4;
  // A clockwise turn is a negative angle in the usual x-right, y-up plane.
  t.iso_ = Eigen::Translation2d(x, y) * Eigen::Rotation2Dd(-t.quarterTurns_ * M_PI / 2.0);
  return t;
}

RoomTransform RoomTransform::fromPose(Cell origin, Dir heading) {
  return fromParts(origin.x, origin.y, static_cast<int>(heading));
}

Cell RoomTransform::apply(Cell c) const {
  const Eigen::Vector2d p = iso_ * Eigen::Vector2d(c.x, c.y);
  return Cell{static_cast<int16_t>(std::lround(p.x())), static_cast<int16_t>(std::lround(p.y()))};
}

RoomTransform RoomTransform::inverse() const {
  const Eigen::Isometry2d inv = iso_.inverse();
  return fromParts(static_cast<int>(std::lround(inv.translation().x())),
                   static_cast<int>(std::lround(inv.translation().y())), (4 - quarterTurns_) % 4);
}

RoomTransform RoomTransform::operator*(const RoomTransform& o) const {
  const Eigen::Isometry2d c = iso_ * o.iso_;
  return fromParts(static_cast<int>(std::lround(c.translation().x())),
                   static_cast<int>(std::lround(c.translation().y())), quarterTurns_ + o.quarterTurns_);
}

}  // namespace nxtmap::network
