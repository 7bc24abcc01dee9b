// Probe: motors and tachometers. Drives motor A forward and B backward at 50 % for 500 ms (a turn on the
// spot), counting pulse-pin edges in the PIOA interrupt with the direction rule; reports the counts.
#include "Probe.hpp"
using namespace probe;

namespace {
constexpr uint32_t kPulse[3] = {1u << 15, 1u << 26, 1u << 0};
constexpr uint32_t kDir[3] = {1u << 1, 1u << 9, 1u << 8};
volatile int32_t g_count[3];
}  // namespace

extern "C" void pio_isr() {
  const uint32_t changed = REG(kIsr);
  const uint32_t lv = REG(kPdsr);
  for (int m = 0; m < 3; ++m) {
    if (!(changed & kPulse[m])) continue;
    const bool pulse = (lv & kPulse[m]) != 0, dir = (lv & kDir[m]) != 0;
    g_count[m] = g_count[m] + (pulse != dir ? 1 : -1);
  }
}

int main() {
  REG(kWdtMr) = 1u << 15;
  pitStart();
  twiInit();
  avrHandshake();
  waitMs(2);
  uint32_t all = 0;
  for (int m = 0; m < 3; ++m) all |= kPulse[m] | kDir[m];
  REG(kPer) = all;
  REG(kOdr) = all;
  (void)REG(kIsr);
  REG(kAicSvr + 8) = reinterpret_cast<uint32_t>(&pio_isr);
  REG(kAicSmr + 8) = 5;
  REG(kAicIecr) = 1u << 2;
  REG(kIer) = kPulse[0] | kPulse[1] | kPulse[2];
  irq_enable();
  avrCommand(50, -50, 0, 0x03, 0);
  waitMs(500);
  avrCommand(0, 0, 0, 0x03, 0);
  waitMs(5);
  for (int m = 0; m < 3; ++m) report(static_cast<uint32_t>(g_count[m]));
  return 0;
}
