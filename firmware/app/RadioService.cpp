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
  // Bytes stay in the UART while LEGO commands wait for replies (its flow control holds the sender).
  uint8_t b;
  while (link_.readyToReceive() && bt_.readByte(b)) link_.receive(b);
  protocol::Command c;
  while (link_.nextCommand(c)) modes_.carryOut(c, nowMs);
}

// Scanning the map for changed cells (MapSync: ~0.45 M instructions, ~10 ms) is too much work to
// repeat in every 1 ms pass, and none is done while the wheels are driven so the motion control keeps
// its 1 ms rhythm: then only the cheap frames go (LEGO replies, status, pose, acks). A waiting reply
// goes at once, without the radio period's pause.
void RadioService::transmit(uint32_t nowMs) {
  if (!bt_.streaming() || bt_.txSpace() < protocol::kMaxFrame) return;
  if (!burst_ && !link_.replyDue() && nowMs - lastSentMs_ < kPeriodMs) return;
  lastSentMs_ = nowMs;
  protocol::Frame f;
  const auto battery = static_cast<uint16_t>(batteryMillivolts(avr_.status().batteryRaw));
  const auto scope = modes_.wheelsDriven() ? protocol::BrickLink::Scope::NoMapScan : protocol::BrickLink::Scope::All;
  burst_ = link_.transmit(nowMs, modes_.report(battery), f, scope);
  if (burst_) (void)bt_.write(f.bytes, f.size);
}

}  // namespace nxtmap::fw
