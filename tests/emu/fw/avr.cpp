// Probe: the AVR link over TWI: handshake, a command frame (motor A 40 %, motor C -25 %, brake on B,
// constant 9 V on ports 1 and 3), then a status frame; reports battery and checksum.
#include "Probe.hpp"
using namespace probe;

int main() {
  REG(kWdtMr) = 1u << 15;
  pitStart();
  twiInit();
  report(avrHandshake() ? 1u : 0u);
  waitMs(2);
  report(avrCommand(40, 0, -25, 0x02, 0x50) ? 1u : 0u);
  uint8_t s[13];
  report(twiRead(s, 13) ? 1u : 0u);
  unsigned sum = 0;
  for (int i = 0; i < 13; ++i) sum += s[i];
  report(sum & 0xFF);                                           // 0xFF when the checksum is right
  report(static_cast<uint32_t>(s[10] | (s[11] << 8)) & 0x3FF);  // battery raw
  // A frame with a wrong checksum must be ignored by the AVR.
  uint8_t bad[9] = {0, 8, 100, 100, 100, 0, 0, 0, 0};
  twiWrite(bad, 9);
  return 0;
}
