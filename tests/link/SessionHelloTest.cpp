// The PC's Session and the brick's HelloReply: a reply of this protocol opens the session and is
// kept (with the brick's grid and range geometry); a brick of another protocol version gets the
// console's "flash the matching firmware" message, whatever the rest of its reply looks like (a
// protocol 3 brick's reply is 5 bytes shorter); a malformed reply of this version changes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::link {
namespace {

using namespace protocol;

void send(Session& pc, const Payload& p, size_t size) {
  PacketHeader h;
  h.op = Op::HelloReply;
  Frame f;
  ASSERT_TRUE(encodePacket(h, p.bytes, size, f));
  pc.receive(f.bytes, f.size, 0);
}

TEST(SessionHello, KeepsTheBricksGeometry) {
  Session pc{SessionConfig{6, 250, 250}};
  HelloReplyMsg r;
  r.session = 6;
  r.gridWidthLog2 = r.gridHeightLog2 = 7;
  r.geometry = RangeGeometryMsg{20, 7, 120, 6, 0};
  Payload p;
  encodeHelloReply(r, p);
  send(pc, p, p.size);
  ASSERT_TRUE(pc.connected());
  ASSERT_TRUE(pc.hello().has_value());
  EXPECT_EQ(pc.hello()->gridWidthLog2, 7);
  const RangeGeometry g = rangeGeometryOf(pc.hello()->geometry);
  EXPECT_EQ(g.cellCm, 20);
  EXPECT_EQ(g.minCm, 7);
  EXPECT_EQ(g.maxCm, 120);
  EXPECT_EQ(g.mountCm, 6);
  EXPECT_EQ(g.sureCm, 0);
  EXPECT_TRUE(pc.error().empty()) << pc.error();
}

TEST(SessionHello, AnotherVersionIsNamedAndAMalformedReplyIgnored) {
  struct Case {
    const char* what;
    uint8_t version;
    size_t size;  // payload bytes sent (16 = protocol 4's whole reply)
    uint8_t cellCm;
    std::string error;  // "" = none
  };
  const std::string other = "the brick speaks protocol version ";
  const Case cases[] = {
      {"protocol 3 (11 bytes)", 3, 11, 10, other + "3, this console " + std::to_string(kProtocolVersion)},
      {"a newer protocol, longer", static_cast<uint8_t>(kProtocolVersion + 1), 16, 10,
       other + std::to_string(kProtocolVersion + 1) + ", this console " + std::to_string(kProtocolVersion)},
      {"this version, truncated", kProtocolVersion, 11, 10, ""},
      {"this version, cell 0", kProtocolVersion, 16, 0, ""},
  };
  for (const Case& c : cases) {
    Session pc{SessionConfig{6, 250, 250}};
    HelloReplyMsg r;
    r.version = c.version;
    r.session = 6;
    r.geometry.cellCm = c.cellCm;
    Payload p;
    encodeHelloReply(r, p);
    send(pc, p, c.size);
    EXPECT_FALSE(pc.connected()) << c.what;
    EXPECT_FALSE(pc.hello().has_value()) << c.what;
    if (c.error.empty()) {
      EXPECT_TRUE(pc.error().empty()) << c.what << ": " << pc.error();
    } else {
      EXPECT_EQ(pc.error().rfind(c.error, 0), 0u) << c.what << ": " << pc.error();
      EXPECT_NE(pc.error().find("flash the matching firmware"), std::string::npos) << c.what;
    }
  }
}

}  // namespace
}  // namespace nxtmap::link
