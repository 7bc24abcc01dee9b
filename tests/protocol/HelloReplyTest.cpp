// HelloReply's range geometry (protocol 4): the brick's cell size, trusted range and sensor mount
// round-trip byte for byte, convert to and from RangeGeometry unchanged, and a reply with an
// impossible geometry is refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {
namespace {

bool sameGeometry(const RangeGeometry& a, const RangeGeometry& b) {
  return a.cellCm == b.cellCm && a.minCm == b.minCm && a.maxCm == b.maxCm && a.mountCm == b.mountCm &&
         a.sureCm == b.sureCm;
}

RangeGeometry geometry(int16_t cellCm, int16_t minCm, int16_t maxCm, int16_t mountCm, int16_t sureCm) {
  RangeGeometry g;
  g.cellCm = cellCm;
  g.minCm = minCm;
  g.maxCm = maxCm;
  g.mountCm = mountCm;
  g.sureCm = sureCm;
  return g;
}

TEST(HelloReply, CarriesTheBricksRangeGeometryUnchanged) {
  struct Case {
    const char* what;
    RangeGeometry g;
  };
  const Case cases[] = {
      {"published (RangeGeometry{})", RangeGeometry{}},
      {"the NXT brick", geometry(20, 7, 120, 6, 0)},
      {"a sure-hit limit", geometry(10, 5, 100, 0, 28)},
      {"sure = min", geometry(10, 5, 100, 0, 5)},
      {"sure = max", geometry(10, 5, 100, 0, 100)},
      {"widest", geometry(255, 254, 255, 50, 255)},
      {"smallest", geometry(1, 0, 1, 0, 0)},
      {"the simulator's largest cells", geometry(169, 5, 254, 0, 0)},
  };
  for (const Case& c : cases) {
    HelloReplyMsg m;
    m.session = 77;
    m.geometry = rangeGeometryMsgOf(c.g);
    Payload p;
    ASSERT_EQ(encodeHelloReply(m, p), 16u) << c.what;
    EXPECT_EQ(p.bytes[11], c.g.cellCm) << c.what;  // after version, session, grid, epoch, path cells, fresh
    HelloReplyMsg d;
    ASSERT_TRUE(decodeHelloReply(p.bytes, p.size, d)) << c.what;
    EXPECT_EQ(d.session, 77u) << c.what;
    EXPECT_TRUE(sameGeometry(rangeGeometryOf(d.geometry), c.g)) << c.what;
  }
}

TEST(HelloReply, TheDefaultGeometryIsThePublishedRobots) {
  EXPECT_TRUE(sameGeometry(rangeGeometryOf(HelloReplyMsg{}.geometry), RangeGeometry{}));
}

TEST(HelloReply, AnImpossibleGeometryIsRefused) {
  struct Case {
    const char* what;
    RangeGeometryMsg g;
    bool accepted;
  };
  const Case cases[] = {
      {"cell 0 (a divisor)", {0, 5, 100, 0, 0}, false},
      {"cell 1", {1, 5, 100, 0, 0}, true},
      {"min = max", {10, 100, 100, 0, 0}, false},
      {"min > max", {10, 120, 100, 0, 0}, false},
      {"min 0", {10, 0, 100, 0, 0}, true},
      {"max 0", {10, 0, 0, 0, 0}, false},
      {"mount 50", {10, 5, 100, 50, 0}, true},
      {"mount 51", {10, 5, 100, 51, 0}, false},
      {"mount 255", {10, 5, 100, 255, 0}, false},
      {"sure below min", {10, 5, 100, 0, 4}, false},
      {"sure above max", {10, 5, 100, 0, 101}, false},
      {"sure 0 (= max)", {10, 5, 100, 0, 0}, true},
  };
  for (const Case& c : cases) {
    HelloReplyMsg m;
    m.geometry = c.g;
    Payload p;
    ASSERT_EQ(encodeHelloReply(m, p), 16u) << c.what;  // the encoder writes what it is given
    HelloReplyMsg d;
    EXPECT_EQ(decodeHelloReply(p.bytes, p.size, d), c.accepted) << c.what;
  }
}

TEST(HelloReply, AProtocol3ReplyWithoutAGeometryIsRefused) {
  HelloReplyMsg m;
  Payload p;
  ASSERT_EQ(encodeHelloReply(m, p), 16u);
  HelloReplyMsg d;
  EXPECT_FALSE(decodeHelloReply(p.bytes, 11, d));  // protocol 3's 11 bytes
}

}  // namespace
}  // namespace nxtmap::protocol
