// The brick the LEGO server tests answer for (LegoServerTest, LegoQueuesTest): its outputs, inputs and speaker
// recorded, an idle robot's context, and telegrams from bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/protocol/LegoServer.hpp"

namespace nxtmap::protocol::test {

using Bytes = std::vector<uint8_t>;

inline Telegram telegramOf(const Bytes& b) {
  Telegram t;
  for (size_t i = 0; i < b.size(); ++i) t.bytes[i] = b[i];
  t.size = static_cast<uint8_t>(b.size());
  return t;
}

// A brick whose outputs, inputs and speaker are recorded.
class FakeBrick final : public LegoBrick {
 public:
  LegoOutputState output(uint8_t port) const override {
    LegoOutputState s;
    s.power = static_cast<int8_t>(-10 * port);
    s.mode = kLegoMotorOn;
    s.runState = kLegoRunRunning;
    s.tachoLimit = 360;
    s.tachoCount = 1000 + port;
    s.blockTachoCount = -2;
    s.rotationCount = 0x01020304;
    return s;
  }
  LegoInputValues input(uint8_t port) const override {
    LegoInputValues v;
    if (port == 3) return v;  // no reading yet
    v.valid = true;
    v.sensorType = kLegoLowSpeed9V;
    v.scaled = v.calibrated = static_cast<int16_t>(40 + port);
    return v;
  }
  uint8_t setOutput(const LegoOutputCommand& c) override {
    set.push_back(c);
    return kLegoOk;
  }
  uint8_t resetPosition(uint8_t port, bool relative) override {
    resets.push_back(port * 2 + (relative ? 1 : 0));
    return kLegoOk;
  }
  void playTone(uint16_t hz, uint16_t ms) override { tones.push_back({hz, ms}); }
  void stopSound() override { ++stops; }
  void address(uint8_t (&a)[6]) const override {
    const uint8_t mine[6] = {0x00, 0x16, 0x53, 0x0A, 0x0B, 0x0C};
    for (int i = 0; i < 6; ++i) a[i] = mine[i];
  }
  uint32_t freeFlashBytes() const override { return 0x00030000; }

  std::vector<LegoOutputCommand> set;
  std::vector<int> resets;
  std::vector<std::pair<uint16_t, uint16_t>> tones;
  int stops = 0;
};

inline LegoContext idle() {
  LegoContext c;
  c.batteryMillivolts = 7980;
  c.sleepLimitMs = 60000;
  c.firmwareMinor = 4;
  return c;
}

inline Bytes cat(Bytes a, const Bytes& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace nxtmap::protocol::test
