// The brick's side of `explore house` played packet by packet for the console's tests: a HelloReply, the
// acknowledgement of each command, then Status packets as the test writes them.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "host/console/HouseExploration.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::console::test {

using protocol::BrickMode;

class HouseByPacket : public ::testing::Test {
 protected:
  void SetUp() override {
    protocol::HelloReplyMsg r;
    r.session = kSession;
    protocol::Payload p;
    protocol::encodeHelloReply(r, p);
    send(protocol::Op::HelloReply, p);
    ASSERT_TRUE(pc.connected());
    status(BrickMode::Idle);  // the brick answered: the house may start
    said = house.start(pc, 0.0);
    acknowledgeCommands();
  }

  // One Status from the brick at `atS` (seconds of the console's clock): in `mode`, in room `roomId` (the
  // brick stands in room 1 when the house starts, whose first room is then 2), standing in `at`.
  void status(BrickMode mode, double atS = 0.0, Cell at = Cell{}, uint16_t roomId = 1) {
    protocol::StatusMsg s;
    s.mode = mode;
    s.roomId = roomId;
    s.pose.cell = at;
    protocol::Payload p;
    ASSERT_GT(protocol::encodeStatus(s, p), 0u);
    send(protocol::Op::Status, p);
    said += house.poll(pc, atS);
  }

  // The brick takes every command the PC has to send (stop-and-wait: one at a time).
  void acknowledgeCommands() {
    for (int i = 0; i < 8 && !pc.commandsDone(); ++i) {
      const std::vector<uint8_t> out = pc.transmit(static_cast<uint32_t>(i) * 1000u);
      protocol::FrameDecoder d;
      protocol::Telegram t;
      for (uint8_t b : out) {
        d.push(b);
        while (d.pop(t)) {
          protocol::PacketView v;
          if (protocol::parsePacket(t, v) && v.header.reliable()) ack_ = v.header.seq;
        }
      }
      status(BrickMode::Exploring);
    }
    ASSERT_TRUE(pc.commandsDone());
  }

  // `count` statuses of `mode` spread evenly over [fromS, toS].
  void statuses(BrickMode mode, int count, double fromS, double toS) {
    for (int i = 0; i < count; ++i) status(mode, fromS + (toS - fromS) * i / (count - 1));
  }

  void send(protocol::Op op, const protocol::Payload& p) {
    protocol::PacketHeader h;
    h.op = op;
    h.ack = ack_;
    h.ackMask = 0xFFFF;
    protocol::Frame f;
    ASSERT_TRUE(protocol::encodePacket(h, p.bytes, p.size, f));
    pc.receive(f.bytes, f.size, 0);
  }

  static constexpr uint32_t kSession = 0x5709;
  link::Session pc{link::SessionConfig{kSession, 250, 250}};
  HouseExploration house;
  std::string said;
  uint16_t ack_ = 0;
};

}  // namespace nxtmap::console::test
