// The PC's Session when the brick goes into another room: the room it left is handed over with
// its map and the robot's last pose there, whichever order the brick's unreliable reports and
// the new room's first map delta arrive in; the new room's cells are not lost.
#include <gtest/gtest.h>

#include <vector>

#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::link {
namespace {

using namespace protocol;

class SessionRoomTest : public ::testing::Test {
 protected:
  void SetUp() override {
    HelloReplyMsg r;
    r.session = 5;
    Payload p;
    encodeHelloReply(r, p);
    send(Op::HelloReply, p);
    ASSERT_TRUE(pc.connected());
  }
  void send(Op op, const Payload& p, uint16_t reliableSeq = 0) {
    PacketHeader h;
    h.op = op;
    h.flags = reliableSeq != 0 ? kFlagReliable : 0;
    h.seq = reliableSeq;
    Frame f;
    ASSERT_TRUE(encodePacket(h, p.bytes, p.size, f));
    pc.receive(f.bytes, f.size, 0);
  }
  void status(uint16_t room, uint16_t epoch, Pose pose) {
    StatusMsg s;
    s.roomId = room;
    s.mapEpoch = epoch;
    s.pose = pose;
    Payload p;
    ASSERT_GT(encodeStatus(s, p), 0u);
    send(Op::Status, p);
  }
  void pose(Pose at) {
    Payload p;
    encodePose(PoseMsg{at}, p);
    send(Op::Pose, p);
  }
  void newRoom(uint16_t room) {
    Payload p;
    encodeNewRoom(NewRoomMsg{room, Cell{0, 0}}, p);
    send(Op::NewRoom, p);
  }
  // One row of cells from (x0, y), `states` in order.
  void delta(uint16_t epoch, int16_t x0, int16_t y, const std::vector<CellState>& states) {
    MapDeltaHeader h;
    h.epoch = epoch;
    h.window = Bounds{x0, y, static_cast<int16_t>(x0 + states.size() - 1), y};
    Payload p;
    MapDeltaWriter w(p, h);
    const uint16_t index = static_cast<uint16_t>((y & 63) * 64 + (x0 & 63));
    ASSERT_TRUE(w.addRun(index, static_cast<uint8_t>(states.size()), [&](uint8_t k) { return states[k]; }));
    send(Op::MapDelta, p, ++deltaSeq);
  }

  Session pc{SessionConfig{5, 250, 250}};
  uint16_t deltaSeq = 0;
  const std::vector<CellState> hall{CellState::Free, CellState::Free, CellState::Free, CellState::Occupied};
};

TEST_F(SessionRoomTest, InOrderTheRoomLeftKeepsItsMapAndTheLastPose) {
  status(0, 1, Pose{Cell{2, 0}, Dir::East});
  delta(1, 0, 0, hall);
  pose(Pose{Cell{0, 0}, Dir::North});  // the new room's start, reported before the room
  newRoom(1);
  delta(2, 0, 0, {CellState::Free});
  const std::vector<RoomChange> changes = pc.takeRoomChanges();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].fromRoom, 0);
  EXPECT_EQ(changes[0].toRoom, 1);
  EXPECT_EQ(changes[0].left.known(), 4u);
  EXPECT_EQ(changes[0].left.at(Cell{3, 0}), CellState::Occupied);
  ASSERT_TRUE(changes[0].lastPose.has_value());
  EXPECT_EQ(changes[0].lastPose->cell, (Cell{2, 0}));
  EXPECT_EQ(changes[0].lastPose->heading, Dir::East);
  EXPECT_EQ(pc.map().known(), 1u);  // the new room only
  EXPECT_TRUE(pc.takeRoomChanges().empty());
}

TEST_F(SessionRoomTest, ANewRoomDeltaOvertakingTheRoomReportLosesNeitherRoom) {
  status(0, 1, Pose{Cell{3, 1}, Dir::South});
  delta(1, 0, 0, hall);
  // The NewRoom message was lost; the new room's first delta comes, then a Status names room 1.
  delta(2, 0, 0, {CellState::Free, CellState::Occupied});
  status(1, 2, Pose{Cell{0, 0}, Dir::North});
  const std::vector<RoomChange> changes = pc.takeRoomChanges();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].left.known(), 4u);
  EXPECT_EQ(changes[0].left.at(Cell{2, 0}), CellState::Free);
  ASSERT_TRUE(changes[0].lastPose.has_value());
  EXPECT_EQ(changes[0].lastPose->cell, (Cell{3, 1}));  // confirmed in room 0 by its Status
  EXPECT_EQ(pc.map().known(), 2u);                     // the new room's cells stay
  EXPECT_EQ(pc.map().at(Cell{1, 0}), CellState::Occupied);
}

TEST_F(SessionRoomTest, ANewRoomDeltaOvertakingTheRoomReportAfterAnEmptyRoomKeepsItsCells) {
  // The brick idle with an empty map (before `explore house`): nothing known in room 0.
  status(0, 1, Pose{Cell{0, 0}, Dir::North});
  // Room 1 starts: its first delta gets through, the Status naming room 1 comes after it.
  delta(2, 0, 0, hall);
  status(1, 2, Pose{Cell{0, 0}, Dir::North});
  const std::vector<RoomChange> changes = pc.takeRoomChanges();
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_EQ(changes[0].left.known(), 0u);
  // The brick was told these cells arrived (acknowledged) and never sends them again.
  EXPECT_EQ(pc.map().known(), 4u);
  EXPECT_EQ(pc.map().at(Cell{3, 0}), CellState::Occupied);
}

TEST_F(SessionRoomTest, AnUploadInTheSameRoomIsNoRoomChange) {
  status(0, 1, Pose{Cell{1, 0}, Dir::North});
  delta(1, 0, 0, hall);
  status(0, 2, Pose{Cell{1, 0}, Dir::North});  // a new epoch (e.g. the PC's upload), same room
  delta(2, 0, 0, hall);
  EXPECT_TRUE(pc.takeRoomChanges().empty());
  EXPECT_EQ(pc.map().known(), 4u);
}

}  // namespace
}  // namespace nxtmap::link
