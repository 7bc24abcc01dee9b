// A command runs exactly once across a reconnect whose acknowledgement was lost (defect #13 of
// issue 15): the real brick protocol (BrickLink, in the stand-in brick) and the real PC Session,
// joined in-process on a millisecond clock. The brick runs the command, every byte back to the
// PC is lost, the link drops, and a new connection starts: to the same brick, after another
// console talked to the brick, or to a brick that restarted.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <vector>

#include "host/link/Session.hpp"
#include "host/link/SimBrick.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::link {
namespace {

sim::World smallRoom() {
  return sim::World::fromRows({"##########", "#........#", "#..#.....#", "#........#", "#....#...#", "##########"});
}

SimBrickConfig brickConfig() {
  SimBrickConfig c;
  c.run.startCol = 1;
  c.run.startRow = 1;
  return c;
}

// One brick and one PC session at a time, joined directly; either direction can be cut.
class Wire {
 public:
  Wire(SimBrick& brick, Session& pc) : brick_(&brick), pc_(&pc) {}

  void tick() {
    ++now_;
    brick_->step(now_);
    const std::vector<uint8_t> toPc = brick_->transmit(now_, 4096);
    if (pcHears && !toPc.empty()) pc_->receive(toPc.data(), toPc.size(), now_);
    const std::vector<uint8_t> toBrick = pc_->transmit(now_);
    if (brickHears && !toBrick.empty()) brick_->receive(toBrick.data(), toBrick.size());
  }
  bool runUntil(const std::function<bool()>& done, uint32_t maxMs) {
    for (uint32_t i = 0; i < maxMs && !done(); ++i) tick();
    return done();
  }
  void run(uint32_t ms) {
    for (uint32_t i = 0; i < ms; ++i) tick();
  }
  // The connection breaks: bytes in flight are gone, both ends are told; it comes back at once,
  // between `brick` and `pc` (the same ones, another console, or a restarted brick).
  void reconnect(SimBrick& brick, Session& pc) {
    brick_->linkLost();
    pc_->linkLost();
    brick_ = &brick;
    pc_ = &pc;
    pcHears = brickHears = true;
  }

  bool pcHears = true;
  bool brickHears = true;

 private:
  SimBrick* brick_;
  Session* pc_;
  uint32_t now_ = 0;
};

struct Fixture {
  sim::World world = smallRoom();
  SimBrick brick{world, brickConfig()};
  Session pc{SessionConfig{0xA1, 250, 250}};
  Wire wire{brick, pc};

  // Connects, sends Explore and lets the brick run it while nothing reaches the PC (the
  // acknowledgement is lost, again and again for each resend); returns its sequence number.
  uint16_t exploreWithItsAckLost() {
    EXPECT_TRUE(wire.runUntil([&] { return pc.connected(); }, 1000));
    wire.pcHears = false;
    const uint16_t seq = pc.explore();
    EXPECT_TRUE(wire.runUntil([&] { return !brick.executed().empty(); }, 1000));
    wire.run(1000);  // the PC resends it a few times; the brick only acknowledges again
    EXPECT_FALSE(pc.acknowledged(seq));
    EXPECT_EQ(brick.executed(), std::vector<uint16_t>{seq});
    return seq;
  }
  // Reconnects to `to` and waits until the session is open and has nothing left to send.
  void reconnectAndSettle(SimBrick& to) {
    wire.reconnect(to, pc);
    EXPECT_TRUE(wire.runUntil([&] { return pc.connected() && pc.commandsDone(); }, 5000));
    wire.run(1000);
  }
};

TEST(SessionReconnect, SameBrickSameSession_TheResentCommandIsOnlyAcknowledged) {
  Fixture f;
  const uint16_t seq = f.exploreWithItsAckLost();
  f.reconnectAndSettle(f.brick);
  EXPECT_EQ(f.brick.executed(), std::vector<uint16_t>{seq});  // once, not twice and not zero times
  EXPECT_TRUE(f.pc.acknowledged(seq));
  EXPECT_GE(f.brick.link().counters().duplicates, 1u);
  EXPECT_TRUE(f.pc.takeUnconfirmed().empty());
  EXPECT_EQ(f.pc.counters().connects, 2u);
}

TEST(SessionReconnect, SameBrickSameSession_ALostCommandRunsOnceAfterTheReconnect) {
  Fixture f;
  ASSERT_TRUE(f.wire.runUntil([&] { return f.pc.connected(); }, 1000));
  f.wire.brickHears = false;  // the command itself is lost, every time
  const uint16_t seq = f.pc.explore();
  f.wire.run(1000);
  ASSERT_TRUE(f.brick.executed().empty());
  f.reconnectAndSettle(f.brick);
  EXPECT_EQ(f.brick.executed(), std::vector<uint16_t>{seq});
  EXPECT_TRUE(f.pc.acknowledged(seq));
}

TEST(SessionReconnect, AnotherConsoleInBetween_TheCommandIsNotRunAgain) {
  Fixture f;
  const uint16_t seq = f.exploreWithItsAckLost();
  // Another console opens its own session with the brick (the brick starts afresh for it)...
  Session other{SessionConfig{0xB2, 250, 250}};
  f.wire.reconnect(f.brick, other);
  ASSERT_TRUE(f.wire.runUntil([&] { return other.connected(); }, 1000));
  f.wire.run(500);
  // ...then the first console comes back: the brick no longer knows its sequence numbers.
  f.reconnectAndSettle(f.brick);
  ASSERT_TRUE(f.pc.hello() && f.pc.hello()->freshSession);
  EXPECT_EQ(f.brick.executed(), std::vector<uint16_t>{seq});  // still once
  const std::vector<UnconfirmedCommand> unconfirmed = f.pc.takeUnconfirmed();
  ASSERT_EQ(unconfirmed.size(), 1u);
  EXPECT_EQ(unconfirmed[0].seq, seq);
  EXPECT_EQ(unconfirmed[0].op, protocol::Op::Explore);
  EXPECT_EQ(f.pc.counters().commandsUnconfirmed, 1u);
  // The session goes on: the next command runs, once.
  const uint16_t stop = f.pc.stop();
  ASSERT_TRUE(f.wire.runUntil([&] { return f.pc.acknowledged(stop); }, 2000));
  EXPECT_EQ(f.brick.executed(), (std::vector<uint16_t>{seq, stop}));
}

TEST(SessionReconnect, ARestartedBrick_TheCommandIsNotRunAgain) {
  Fixture f;
  const uint16_t seq = f.exploreWithItsAckLost();
  SimBrick restarted(f.world, brickConfig());  // power-on: nothing of the old session is left
  f.reconnectAndSettle(restarted);
  EXPECT_EQ(f.brick.executed().size() + restarted.executed().size(), 1u);
  EXPECT_TRUE(restarted.executed().empty());
  const std::vector<UnconfirmedCommand> unconfirmed = f.pc.takeUnconfirmed();
  ASSERT_EQ(unconfirmed.size(), 1u);
  EXPECT_EQ(unconfirmed[0].seq, seq);
  const uint16_t again = f.pc.explore();  // what the user does when told
  ASSERT_TRUE(f.wire.runUntil([&] { return f.pc.acknowledged(again); }, 2000));
  EXPECT_EQ(restarted.executed(), std::vector<uint16_t>{again});
}

TEST(SessionReconnect, ARestartedBrick_ACommandNeverSentBeforeIsSentOnce) {
  Fixture f;
  const uint16_t first = f.exploreWithItsAckLost();
  const uint16_t queued = f.pc.stop();  // queued behind the unacknowledged one, never sent
  SimBrick restarted(f.world, brickConfig());
  f.reconnectAndSettle(restarted);
  EXPECT_EQ(f.brick.executed(), std::vector<uint16_t>{first});
  EXPECT_EQ(restarted.executed(), std::vector<uint16_t>{queued});
  EXPECT_TRUE(f.pc.acknowledged(queued));
}

}  // namespace
}  // namespace nxtmap::link
