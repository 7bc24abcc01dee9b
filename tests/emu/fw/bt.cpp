// Probe: the Bluetooth module on USART1. Releases RESET (PA11), waits for RESET_INDICATION, opens the
// port, accepts the PC's connection, opens the stream, waits for the CMD signal (ADC 6), raises
// ARM7_CMD (PA27), then echoes 4 stream bytes + 1 back through the PDC. With hardware handshaking the
// USART holds RTS high unless a receive PDC buffer is set (RCR or RNCR non-zero), so even single bytes
// are received through the PDC (a one-byte buffer each).
#include "Probe.hpp"
using namespace probe;

namespace {
constexpr uint32_t kUs = 0xFFFC4000;
constexpr uint32_t kCr = kUs, kMr = kUs + 4, kCsr = kUs + 0x14, kThr = kUs + 0x1C, kBrgr = kUs + 0x20,
                   kRpr = kUs + 0x100, kRcr = kUs + 0x104, kTpr = kUs + 0x108, kTcr = kUs + 0x10C, kPtcr = kUs + 0x120;
constexpr uint32_t kAdc = 0xFFFD8000;

volatile uint8_t g_byte;
uint8_t getByte() {
  REG(kRpr) = reinterpret_cast<uint32_t>(&g_byte);
  REG(kRcr) = 1;
  REG(kPtcr) = 1;  // RXTEN
  while (REG(kRcr) != 0) {}
  return g_byte;
}
void putByte(uint8_t b) {
  while (!(REG(kCsr) & 2)) {}
  REG(kThr) = b;
}
// Command-mode frame to the BC4: TX checksum over cmd+payload, big-endian.
void sendCmd(const uint8_t* cmdAndPayload, int n) {
  unsigned sum = 0;
  for (int i = 0; i < n; ++i) sum += cmdAndPayload[i];
  const unsigned cs = (0x10000u - sum) & 0xFFFF;
  putByte(static_cast<uint8_t>(n + 2));
  for (int i = 0; i < n; ++i) putByte(cmdAndPayload[i]);
  putByte(static_cast<uint8_t>(cs >> 8));
  putByte(static_cast<uint8_t>(cs));
}
// Receives one frame into buf ([cmd][payload...]); returns its command or -1 on a bad checksum.
int recvFrame(uint8_t* buf) {
  const uint8_t len = getByte();
  unsigned sum = len;
  for (int i = 0; i < len; ++i) buf[i] = getByte();
  for (int i = 0; i < len - 2; ++i) sum += buf[i];
  const unsigned cs = (static_cast<unsigned>(buf[len - 2]) << 8) | buf[len - 1];
  return ((sum + cs) & 0xFFFF) == 0 ? buf[0] : -1;
}
uint8_t g_rx[8];
uint8_t g_tx[8];
}  // namespace

int main() {
  REG(kWdtMr) = 1u << 15;
  pitStart();
  REG(kPmcPcer) = (1u << 7) | (1u << 2) | (1u << 4);
  REG(kPer) = (1u << 11) | (1u << 27) | (1u << 31);
  REG(kCodr) = (1u << 11) | (1u << 27);
  REG(kSodr) = 1u << 31;
  REG(kOer) = (1u << 11) | (1u << 27) | (1u << 31);
  REG(kPdr) = (1u << 21) | (1u << 22) | (1u << 24) | (1u << 25);
  REG(kAsr) = (1u << 21) | (1u << 22) | (1u << 24) | (1u << 25);
  REG(kCr) = (1u << 2) | (1u << 3) | (1u << 5) | (1u << 7);
  REG(kMr) = 2u | (3u << 6) | (4u << 9) | (1u << 19);  // HW handshake, 8N1, OVER
  REG(kBrgr) = 13;
  REG(kCr) = (1u << 4) | (1u << 6);
  waitMs(100);
  REG(kSodr) = 1u << 11;  // release the BC4's RESET
  uint8_t f[40];
  report(static_cast<uint32_t>(recvFrame(f)));  // 0x14 RESET_INDICATION
  const uint8_t openPort[] = {0x03};
  sendCmd(openPort, 1);
  report(static_cast<uint32_t>(recvFrame(f)));  // 0x1B PORT_OPEN_RESULT
  report(static_cast<uint32_t>(recvFrame(f)));  // 0x16 REQUEST_CONNECTION (the PC dialled in)
  const uint8_t accept[] = {0x09, 0x01};
  sendCmd(accept, 2);
  report(static_cast<uint32_t>(recvFrame(f)));  // 0x13 CONNECT_RESULT
  const uint8_t handle = f[2];
  const uint8_t openStream[] = {0x0B, handle};
  sendCmd(openStream, 2);
  REG(kAdc + 0x10) = 1u << 6;
  uint32_t cmd = 0;
  for (int i = 0; i < 1000 && cmd <= 0x200; ++i) {
    waitMs(1);
    REG(kAdc) = 2;
    while (!(REG(kAdc + 0x1C) & (1u << 6))) {}
    cmd = REG(kAdc + 0x30 + 6 * 4);
  }
  report(cmd > 0x200 ? 1u : 0u);
  REG(kSodr) = 1u << 27;  // stream (data) mode
  REG(kRpr) = reinterpret_cast<uint32_t>(g_rx);
  REG(kRcr) = 4;
  REG(kPtcr) = 1;
  while (!(REG(kCsr) & (1u << 3))) {}  // ENDRX
  for (int i = 0; i < 4; ++i) g_tx[i] = static_cast<uint8_t>(g_rx[i] + 1);
  g_tx[4] = '!';
  REG(kTpr) = reinterpret_cast<uint32_t>(g_tx);
  REG(kTcr) = 5;
  REG(kPtcr) = 1u << 8;
  while (!(REG(kCsr) & (1u << 9))) {}  // TXEMPTY
  waitMs(1);
  return 0;
}
