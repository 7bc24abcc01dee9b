// LEGO's own firmware 1.29 (Debian's nxt-firmware, unmodified) counts motor rotation with its own
// tachometer code: TC0..TC2 in capture mode on the encoder pulse pins (TIOA), the direction pin read in the
// handler (d_output.r). A PC tool (LegoClient: the Bluetooth Developer Kit's tables) connects over the
// emulated Bluetooth link once LEGO's firmware has opened its port, turns motor A with SET_OUTPUT_STATE,
// reads GET_OUTPUT_STATE while it turns and after it is braked, and each tacho count must lie between the
// emulated encoder's degrees when the request left and when the reply arrived (the firmware sampled it in
// between), within kSlackDeg.
#include "LegoBrickSession.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace nxtmap::emu::lego {
namespace {

const std::string kLegoImage = "/usr/share/nxt-firmware/nxt_firmware.bin";
constexpr double kSlackDeg = 2.0;  // one encoder edge each side, and the brake's last edge

std::string whyNotRun() {
#if defined(__SANITIZE_ADDRESS__)
  return "LEGO's firmware never idles (0.4 x real time under ASan): make test runs this from the Release build";
#else
  return std::ifstream(kLegoImage).good() ? std::string()
                                          : kLegoImage + " is absent (Debian package nxt-firmware, make deps)";
#endif
}

int32_t tachoCount(const Reply& r) { return static_cast<int32_t>(r.u32(13)); }  // after limit (9..12)

TEST(LegoTachoEndToEnd, GetOutputStateCountsTheEmulatedMotorsDegrees) {
  if (const std::string why = whyNotRun(); !why.empty()) GTEST_SKIP() << why;
  std::vector<Step> script;
  const auto add = [&](const Bytes& request) { script.push_back({request, false}); };
  add(getOutputState(0));  // at rest: 0
  add(setOutputState(0, 75, kMotorOn | kBrake, 0, 0, kRunning, 0));
  for (int i = 0; i < 6; ++i) add(getOutputState(0));  // turning, 300 ms apart
  add(setOutputState(0, 0, kMotorOn | kBrake, 0, 0, kRunning, 0));
  for (int i = 0; i < 3; ++i) add(getOutputState(0));  // braked
  add(setOutputState(0, -60, kMotorOn | kBrake, 0, 0, kRunning, 0));
  for (int i = 0; i < 4; ++i) add(getOutputState(0));  // backwards
  SessionOptions o;
  o.firmware = kLegoImage;
  o.startAtS = 6.0;  // LEGO's menu is up at 5 s
  o.gapMs = 300;
  o.maxSeconds = 40;
  const SessionResult s = runSession(script, o);
  ASSERT_EQ(s.error, "");
  ASSERT_EQ(s.exchanges.size(), script.size());
  double mostTurned = 0;
  for (size_t i = 0; i < s.exchanges.size(); ++i) {
    const Exchange& e = s.exchanges[i];
    SCOPED_TRACE("request " + std::to_string(i) + " at " + std::to_string(e.sentMs) + " ms");
    ASSERT_TRUE(e.answered);
    EXPECT_EQ(e.reply.opcode(), e.request[1]);
    EXPECT_EQ(e.reply.status(), kSuccess);
    if (e.request[1] != kGetOutputState) continue;
    const double count = tachoCount(e.reply);
    const double lo = std::min(e.motorADegAtSend, e.motorADegAtReply) - kSlackDeg;
    const double hi = std::max(e.motorADegAtSend, e.motorADegAtReply) + kSlackDeg;
    EXPECT_GE(count, lo) << "LEGO's tacho count against the emulated encoder";
    EXPECT_LE(count, hi) << "LEGO's tacho count against the emulated encoder";
    mostTurned = std::max(mostTurned, std::abs(e.motorADegAtReply));
    std::printf("  %7.1f ms  tacho count %6.0f  encoder %8.1f .. %8.1f deg\n", e.sentMs, count, e.motorADegAtSend,
                e.motorADegAtReply);
  }
  EXPECT_GT(mostTurned, 360.0) << "motor A hardly turned: the test proves nothing";
}

}  // namespace
}  // namespace nxtmap::emu::lego
