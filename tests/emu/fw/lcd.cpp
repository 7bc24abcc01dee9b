// Probe: the LCD on SPI. Init as NxOS/LEGO do, then page 0 columns 0..9 all dark (PDC), and a single pixel
// at (50, 20) (page 2, bit 4) written byte by byte through TDR. Built a second time as lcdfault.elf, which
// sends the byte 0x3A (no UC1601 command) after the init.
#include "Probe.hpp"
using namespace probe;

namespace {
constexpr uint32_t kSpi = 0xFFFE0000;
constexpr uint32_t kCr = kSpi, kMr = kSpi + 4, kTdr = kSpi + 0x0C, kSr = kSpi + 0x10, kCsr0 = kSpi + 0x30,
                   kTpr = kSpi + 0x108, kTcr = kSpi + 0x10C, kPtcr = kSpi + 0x120;
constexpr uint32_t kA0 = 1u << 12, kCs = 1u << 10;
uint8_t g_page[100];

void send(bool data, uint8_t b) {
  while (!(REG(kSr) & (1u << 9))) {}  // TXEMPTY before A0 changes
  if (data)
    REG(kSodr) = kA0;
  else
    REG(kCodr) = kA0;
  REG(kTdr) = b;
}
}  // namespace

int main() {
  REG(kWdtMr) = 1u << 15;
  REG(kPmcPcer) = (1u << 5) | (1u << 2);
  REG(kPer) = kA0 | kCs;
  REG(kOer) = kA0 | kCs;
  REG(kCodr) = kCs;
  REG(kPdr) = (1u << 13) | (1u << 14);
  REG(kAsr) = (1u << 13) | (1u << 14);
  REG(kCr) = 0x80;
  REG(kCr) = 1;
  REG(kMr) = 1u | (1u << 4);
  REG(kCsr0) = (24u << 8) | 1u;
  const uint8_t init[] = {0xE2, 0xEB, 0x2F, 0xA4, 0xA6, 0x40, 0x81, 0x5A, 0xC4, 0x27, 0x29, 0xA0, 0x89, 0x23, 0xAF};
  for (uint8_t c : init) send(false, c);
#ifdef NXTMAP_PROBE_UNKNOWN_COMMAND
  send(false, 0x3A);  // not a UC1601 command: the strict LCD stops the run here
  while (!(REG(kSr) & (1u << 9))) {}
  for (volatile int i = 0; i < 20000; ++i) {}  // time for the run to stop before the rest
#endif
  for (int i = 0; i < 100; ++i) g_page[i] = i < 10 ? 0xFF : 0x00;
  send(false, 0x00);
  send(false, 0x10);
  send(false, 0xB0);
  while (!(REG(kSr) & (1u << 9))) {}
  REG(kSodr) = kA0;
  REG(kTpr) = reinterpret_cast<uint32_t>(g_page);
  REG(kTcr) = 100;
  REG(kPtcr) = 1u << 8;
  while (!(REG(kSr) & (1u << 9))) {}
  send(false, 0x02);  // column 50 = 0x32
  send(false, 0x13);
  send(false, 0xB2);
  send(true, 0x10);
  while (!(REG(kSr) & (1u << 9))) {}
  return 0;
}
