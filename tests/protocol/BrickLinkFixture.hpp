// The brick's end of the link as the BrickLink tests drive it (BrickLinkTest, BrickLinkCommandsTest): bytes
// fed in as the firmware feeds them, everything it sends decoded, the PC's Hello, and the commands it hands on.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/protocol/BrickLink.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol::test {

using Bytes = std::vector<uint8_t>;

struct Received {
  std::vector<PacketHeader> headers;
  std::vector<Bytes> payloads;
  std::vector<Telegram> lego;
  size_t count(Op op) const {
    size_t n = 0;
    for (const PacketHeader& h : headers) n += h.op == op ? 1 : 0;
    return n;
  }
  const Bytes* last(Op op) const {
    for (size_t i = headers.size(); i-- > 0;) {
      if (headers[i].op == op) return &payloads[i];
    }
    return nullptr;
  }
};

class BrickLinkTest : public ::testing::Test {
 protected:
  void feed(const Bytes& b) {
    for (uint8_t x : b) link.receive(x);
  }
  // Everything the brick wants to send now, decoded.
  Received collect(uint32_t now) {
    Received r;
    Frame f;
    FrameDecoder d;
    while (link.transmit(now, report, f)) {
      for (uint8_t i = 0; i < f.size; ++i) d.push(f.bytes[i]);
      Telegram t;
      while (d.pop(t)) {
        PacketView v;
        if (parsePacket(t, v)) {
          r.headers.push_back(v.header);
          r.payloads.emplace_back(v.payload, v.payload + v.payloadSize);
          if (v.header.op == Op::MapDelta) {
            mirror.apply(v.payload, v.payloadSize);
            received.record(v.header.seq);
          }
        } else {
          r.lego.push_back(t);
        }
      }
    }
    return r;
  }
  void hello(uint32_t session, bool wantMap = false) {
    Payload p;
    encodeHello(HelloMsg{kProtocolVersion, session, wantMap}, p);
    feed(test::pcPacket(Op::Hello, 0, received, &p));
  }
  std::vector<Command> commands() {
    std::vector<Command> out;
    Command c;
    while (link.nextCommand(c)) out.push_back(c);
    return out;
  }

  test::OwnedGrid<> o;
  BrickLink link{o.grid, o.shadow, BrickLinkConfig{}};
  BrickReport report;
  SeqWindow received;  // the PC's record of the brick's reliable seqs
  test::MirrorMap mirror;
};

}  // namespace nxtmap::protocol::test
