// A LEGO command between two of ours never delays or corrupts ours: the PC's own Session (explore, status,
// map) and a LEGO tool share the emulated link to the real firmware; the tool's requests go out between the
// Session's frames every few milliseconds. The Session must see the same thing as without the tool: no
// damaged byte, the explore command acknowledged as early, the status reports as often.
#include "LegoBrickSession.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/link/Session.hpp"
#include "host/sim/World.hpp"

#include <gtest/gtest.h>

#include <functional>

namespace nxtmap::emu::lego {
namespace {

struct Shared {
  double ackMs = -1;      // when the explore command was acknowledged
  uint64_t statuses = 0;  // status reports in the window
  uint32_t skipped = 0;   // bytes the Session's decoder threw away
  size_t legoSent = 0, legoAnswered = 0, legoWrong = 0;
  std::string error;
};

// The kit's reply size, or the 3 bytes of LEGO's unknown-command status for a command the brick does not serve.
size_t expectedReplySize(const Bytes& request) { return request[1] == kLsGetStatus ? 3 : replySize(request); }

constexpr uint32_t kExploreAtMs = 2000, kEndMs = 8000;

// `lego` gives the request to send at a ms (empty: none this ms).
Shared runShared(const std::function<Bytes(uint32_t ms)>& lego) {
  Shared out;
  ElfLoad load = ElfImage::load(simFirmwarePath());
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  if (!load.image || !world.world) {
    out.error = "cannot load the image or the world";
    return out;
  }
  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 1;
  o.brick.startRow = 20;
  o.brick.heading = sim::Heading::N;
  o.brick.link = &radio;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = kEndMs / 1000.0 + 1;
  link::Session pc;
  TelegramSplitter fromBrick;
  std::deque<Bytes> legoWaiting;  // the tool's requests waiting for replies, in order
  uint32_t lastMs = 0;
  uint16_t exploreSeq = 0;
  bool exploreSent = false;
  uint64_t statusesAtStart = 0;
  o.onEvent = [&](uint64_t cycles) {
    const auto ms = static_cast<uint32_t>(cycles / (kMckHz / 1000));
    if (ms == lastMs) return false;
    lastMs = ms;
    fromBrick.push(radio.fromBrick.data(), radio.fromBrick.size());
    radio.fromBrick.clear();
    Bytes t;
    while (fromBrick.pop(t)) {
      if (!t.empty() && t[0] == kReply) {  // the tool's
        if (legoWaiting.empty() || t[1] != legoWaiting.front()[1] || t.size() != expectedReplySize(legoWaiting.front()))
          ++out.legoWrong;
        if (!legoWaiting.empty()) legoWaiting.pop_front();
        ++out.legoAnswered;
        continue;
      }
      const Bytes f = framed(t);  // the Session's, as it came
      pc.receive(f.data(), f.size(), ms);
    }
    const std::vector<uint8_t> ours = pc.transmit(ms);
    radio.toBrick.insert(radio.toBrick.end(), ours.begin(), ours.end());
    const Bytes request = lego(ms);
    if (!request.empty() && pc.connected()) {  // between our frames, never inside one
      const Bytes f = framed(request);
      radio.toBrick.insert(radio.toBrick.end(), f.begin(), f.end());
      legoWaiting.push_back(request);
      ++out.legoSent;
    }
    if (!exploreSent && ms >= kExploreAtMs && pc.connected()) {
      exploreSeq = pc.explore();
      exploreSent = true;
      statusesAtStart = pc.statusesReceived();
    }
    if (exploreSent && out.ackMs < 0 && pc.acknowledged(exploreSeq)) out.ackMs = ms;
    return ms >= kEndMs;
  };
  EmulatedRun e(*load.image, *world.world, o);
  const EmulatedRunReport r = e.run();
  if (r.fault) out.error = r.fault.describe();
  out.statuses = pc.statusesReceived() - statusesAtStart;
  out.skipped = pc.decoderCounters().skipped;
  return out;
}

void expectOursUnchanged(const std::function<Bytes(uint32_t ms)>& lego) {
  const Shared alone = runShared([](uint32_t) { return Bytes{}; });
  const Shared shared = runShared(lego);
  ASSERT_EQ(alone.error, "");
  ASSERT_EQ(shared.error, "");
  ASSERT_GE(alone.ackMs, 0) << "explore never acknowledged without the tool";
  EXPECT_GE(shared.ackMs, 0) << "explore never acknowledged with the tool";
  EXPECT_LE(shared.ackMs, alone.ackMs + 50) << "acknowledged later than alone (emulated ms)";
  EXPECT_GE(shared.statuses + 1, alone.statuses) << "fewer status reports with the tool";
  EXPECT_EQ(shared.skipped, 0u) << "bytes the Session's decoder threw away";
  EXPECT_GT(shared.legoSent, 100u);
  EXPECT_EQ(shared.legoAnswered, shared.legoSent);
  EXPECT_EQ(shared.legoWrong, 0u);
}

TEST(LegoBetweenOursEndToEnd, ServedLegoCommandsBetweenOurFramesNeverDelayOrCorruptOurs) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the emulated brick at ASan speed: make test runs this from the Release build (EndToEnd)";
#endif
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  expectOursUnchanged([](uint32_t ms) {
    if (ms < 500 || ms % 37 != 0) return Bytes{};
    return ms % 2 ? getBatteryLevel() : keepAlive();
  });
}

// The same with commands the brick does not serve mixed in (each must get LEGO's unknown-command status).
TEST(LegoBetweenOursEndToEnd, UnservedLegoCommandsBetweenOurFramesNeverDelayOrCorruptOurs) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the emulated brick at ASan speed: make test runs this from the Release build (EndToEnd)";
#endif
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  expectOursUnchanged([](uint32_t ms) {
    if (ms < 500 || ms % 37 != 0) return Bytes{};
    return ms % 3 == 0 ? lsGetStatus(1) : getBatteryLevel();
  });
}

}  // namespace
}  // namespace nxtmap::emu::lego
