#include <gtest/gtest.h>

#include <vector>

#include "firmware/app/PathFollower.hpp"

namespace nxtmap::fw {
namespace {

protocol::PathMsg pathOf(std::vector<Cell> cells, uint16_t id = 7) {
  protocol::PathMsg p;
  p.pathId = id;
  p.start = cells[0];
  p.count = 1;
  for (size_t i = 1; i < cells.size(); ++i) EXPECT_TRUE(p.append(cells[i]));
  return p;
}

// Runs a path to its end, answering every action as carried out (or a drive blocked at `blockAt`).
std::vector<DriveAction> follow(PathFollower& f, int blockAtDrive = -1) {
  std::vector<DriveAction> actions;
  DriveAction a;
  bool more = f.next(nullptr, a);
  int drives = 0;
  while (more && actions.size() < 100) {
    actions.push_back(a);
    DriveEvent e =
        a.kind == DriveAction::Kind::Rotate ? DriveEvent::rotated() : DriveEvent::driven(drives++ == blockAtDrive);
    more = f.next(&e, a);
  }
  return actions;
}

TEST(PathFollower, TurnsOnlyWhereThePathChangesDirection) {
  PathFollower f;
  ASSERT_TRUE(f.start(pathOf({{0, 0}, {0, 1}, {0, 2}, {1, 2}}), Pose{{0, 0}, Dir::North}, 200));
  const auto a = follow(f);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].kind, DriveAction::Kind::Drive);
  EXPECT_EQ(a[0].value, 200);
  EXPECT_EQ(a[1].value, 200);
  EXPECT_EQ(a[2].kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(a[2].value, 1570);  // a quarter turn clockwise (2 x 785 mrad)
  EXPECT_EQ(a[3].kind, DriveAction::Kind::Drive);
  EXPECT_EQ(f.progress().state, protocol::PathState::Reached);
  EXPECT_EQ(f.progress().reached, 3);
  EXPECT_EQ(f.pose().cell, (Cell{1, 2}));
  EXPECT_EQ(f.pose().heading, Dir::East);
  EXPECT_FALSE(f.active());
}

TEST(PathFollower, DiagonalStepsDriveLongerAndEndOnAnAxis) {
  PathFollower f;
  ASSERT_TRUE(f.start(pathOf({{0, 0}, {1, 1}}), Pose{{0, 0}, Dir::North}, 200));
  const auto a = follow(f);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].value, 785);   // to north-east
  EXPECT_EQ(a[1].value, 282);   // 200 x 1.414
  EXPECT_EQ(a[2].value, -785);  // back onto the north axis
  EXPECT_EQ(f.pose().heading, Dir::North);
  EXPECT_EQ(f.pose().cell, (Cell{1, 1}));
}

TEST(PathFollower, TurnsTheShorterWay) {
  PathFollower f;
  ASSERT_TRUE(f.start(pathOf({{0, 0}, {-1, 0}}), Pose{{0, 0}, Dir::North}, 200));
  const auto a = follow(f);
  ASSERT_GE(a.size(), 1u);
  EXPECT_EQ(a[0].value, -1570);  // west: a quarter anticlockwise, not three quarters clockwise
}

TEST(PathFollower, ABlockedDriveEndsThePathAtTheCellItCouldNotEnter) {
  PathFollower f;
  ASSERT_TRUE(f.start(pathOf({{0, 0}, {0, 1}, {0, 2}, {0, 3}}), Pose{{0, 0}, Dir::North}, 200));
  follow(f, 1);
  EXPECT_EQ(f.progress().state, protocol::PathState::Blocked);
  EXPECT_EQ(f.progress().reached, 1);
  EXPECT_EQ(f.progress().at, (Cell{0, 2}));
  EXPECT_EQ(f.pose().cell, (Cell{0, 1}));
}

TEST(PathFollower, APathNotStartingAtTheRobotIsRefused) {
  PathFollower f;
  EXPECT_FALSE(f.start(pathOf({{3, 3}, {3, 4}}), Pose{{0, 0}, Dir::North}, 200));
  EXPECT_FALSE(f.active());
  EXPECT_EQ(f.progress().state, protocol::PathState::None);
}

}  // namespace
}  // namespace nxtmap::fw
