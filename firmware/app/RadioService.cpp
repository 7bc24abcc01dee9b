#include "firmware/app/RadioService.hpp"

namespace nxtmap::fw {

void RadioService::serve(uint32_t nowMs) {
  receive(nowMs);
  transmit(nowMs);
}

void RadioService::receive(uint32_t nowMs) {
  const uint32_t epoch = bt_.linkEpoch();
  bt_.poll(nowMs);
  if (bt_.linkEpoch() != epoch) link_.linkLost();
  uint8_t b;
  while (bt_.readByte(b)) link_.receive(b);
  protocol::Command c;
  while (link_.nextCommand(c)) modes_.carryOut(c, nowMs);
}

// Building a frame scans the map (MapSync: ~0.45 M instructions, ~10 ms), too much work to repeat
// in every 1 ms pass, and none while the wheels are driven so the motion control keeps its 1 ms
// rhythm.
void RadioService::transmit(uint32_t nowMs) {
  if (!bt_.streaming() || bt_.txSpace() < protocol::kMaxFrame) return;
  if (modes_.wheelsDriven()) return;
  if (!burst_ && nowMs - lastSentMs_ < kPeriodMs) return;
  lastSentMs_ = nowMs;
  protocol::Frame f;
  const auto battery = static_cast<uint16_t>(batteryMillivolts(avr_.status().batteryRaw));
  burst_ = link_.transmit(nowMs, modes_.report(battery), f);
  if (burst_) (void)bt_.write(f.bytes, f.size);
}

}  // namespace nxtmap::fw
