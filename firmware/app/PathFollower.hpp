#pragma once
#include <cstdint>

#include "common/explore/Pose.hpp"
#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/protocol/Messages.hpp"

namespace nxtmap::fw {

// Follows a path from the PC (8-neighbour cells, cell 0 = where the robot stands): for each step,
// rotate to the step's direction (eighths of a turn, the shorter way) and drive one cell (x sqrt 2
// on a diagonal). At the end the robot turns back onto the nearest axis, so its heading is one of
// the four the explorer knows. A blocked drive stops the path (state Blocked, `at` = the cell it
// could not enter). Pure logic: feed the answer to each action, get the next.
class PathFollower {
 public:
  static constexpr int32_t kMradPerEighth = 785;

  // Starts `path`; false (nothing changes) when the path does not start at the robot's cell.
  bool start(const protocol::PathMsg& path, Pose pose, int32_t cellMm) {
    if (path.count == 0 || path.start != pose.cell) return false;
    path_ = path;
    cellMm_ = cellMm;
    cell_ = pose.cell;
    eighths_ = static_cast<uint8_t>(2 * static_cast<uint8_t>(pose.heading));
    progress_ = protocol::PathProgressMsg{path.pathId, 0, protocol::PathState::Following, pose.cell};
    step_ = Step::Plan;
    return true;
  }
  bool active() const { return step_ != Step::Idle; }
  const protocol::PathProgressMsg& progress() const { return progress_; }
  // The robot's cell and (axis) heading as far as the path knows.
  Pose pose() const { return Pose{cell_, static_cast<Dir>((eighths_ / 2) & 3)}; }
  // Stops following (state Aborted) if a path is running.
  void abort() {
    if (step_ == Step::Idle) return;
    step_ = Step::Idle;
    progress_.state = protocol::PathState::Aborted;
  }

  // The next action; `answer` is the event that ended the previous one (nullptr at the start).
  // Returns false when the path is over (progress() tells how).
  bool next(const DriveEvent* answer, DriveAction& out) {
    if (step_ == Step::Driving && answer != nullptr && answer->kind == DriveEvent::Kind::Driven) {
      if (answer->blocked) {
        progress_.state = protocol::PathState::Blocked;
        progress_.at = path_.cellAt(static_cast<uint16_t>(progress_.reached + 1));
        return finishOnAxis(out);
      }
      ++progress_.reached;
      cell_ = path_.cellAt(progress_.reached);
      progress_.at = cell_;
      step_ = Step::Plan;
    }
    if (step_ == Step::Straighten) {
      step_ = Step::Idle;
      return false;
    }
    if (step_ != Step::Plan && step_ != Step::Turning) return false;
    if (progress_.reached + 1 >= path_.count) {
      progress_.state = protocol::PathState::Reached;
      return finishOnAxis(out);
    }
    const uint8_t want = eighthOf(cell_, path_.cellAt(static_cast<uint16_t>(progress_.reached + 1)));
    if (want != eighths_) {
      out = DriveAction::rotate(turnTo(want));
      step_ = Step::Turning;
      return true;
    }
    out = DriveAction::drive((want & 1u) ? cellMm_ * 1414 / 1000 : cellMm_);
    step_ = Step::Driving;
    return true;
  }

 private:
  enum class Step : uint8_t { Idle, Plan, Turning, Driving, Straighten };

  // Direction of an 8-neighbour step in eighths clockwise from North (+y).
  static uint8_t eighthOf(Cell from, Cell to) {
    static constexpr uint8_t kTable[3][3] = {{5, 6, 7}, {4, 0, 0}, {3, 2, 1}};  // [dx+1][dy+1]
    return kTable[to.x - from.x + 1][to.y - from.y + 1];
  }
  // Rotation (mrad) from the current heading to `want`, the shorter way; updates the heading.
  int32_t turnTo(uint8_t want) {
    int delta = (want - eighths_ + 8) % 8;
    if (delta > 4) delta -= 8;
    eighths_ = want;
    return delta * kMradPerEighth;
  }
  bool finishOnAxis(DriveAction& out) {
    if ((eighths_ & 1u) == 0) {
      step_ = Step::Idle;
      return false;
    }
    out = DriveAction::rotate(turnTo(static_cast<uint8_t>((eighths_ + 7) % 8)));  // back to the axis
    step_ = Step::Straighten;
    return true;
  }

  protocol::PathMsg path_{};
  protocol::PathProgressMsg progress_{};
  int32_t cellMm_ = 200;
  Cell cell_{};
  uint8_t eighths_ = 0;
  Step step_ = Step::Idle;
};

}  // namespace nxtmap::fw
