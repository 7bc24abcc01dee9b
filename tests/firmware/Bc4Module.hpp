// The BC4 Bluetooth module at register level, shared by the BlueCore driver's tests (BlueCoreTest,
// BlueCoreStreamTest): the module and its USART1 + PDC as the driver sees them, and milliseconds of the
// main loop.
#pragma once

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "firmware/board/At91sam7s.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {

// USART1 + PDC + the BC4 module at register level. The module answers OPEN_PORT, ACCEPT_CONNECTION
// and OPEN_STREAM (raising its CMD line, read through ADC channel 6), checks the ARM's checksum rule,
// and while the ARM holds ARM7_CMD high exchanges raw bytes (data mode). A PDC transfer may be held
// (holdTx) to stand for bytes still on their way; TXTDIS abandons it, and its counters keep what was
// left (as the PDC's do: a transfer enabled later sends TCR bytes, then TNCR bytes from TNPR). Bytes to the ARM go through the
// receive PDC (RPR/RCR chained to RNPR/RNCR) and only while RTS is low: hardware handshaking holds RTS
// high while the receiver is off or RCR = RNCR = 0 (deliver()).
struct Bc4 {
  FakeBus bus;
  std::deque<uint8_t> toArm;
  std::vector<uint8_t> fromArm;                // raw bytes received (stream mode)
  std::vector<std::vector<uint8_t>> commands;  // command frames received (command mode)
  bool cmdLine = false, resetHeld = true, badChecksum = false, indicateReset = true, answerOpenPort = true;
  bool answerAddress = true;
  std::vector<uint8_t> localAddress{0x00, 0x16, 0x53, 0x12, 0x34, 0x56, 0x00};  // GET_LOCAL_ADDR_RESULT's 7 bytes
  bool armCmd = false;                                                          // ARM7_CMD (PA27): high = data mode
  bool holdTx = false;
  bool rxPdc = false;           // receive PDC enabled (PTCR RXTEN)
  std::vector<uint8_t> heldTx;  // a PDC transfer not sent yet
  std::vector<uint8_t> pinAnswer;

  Bc4() {
    using namespace reg;
    bus.onRead = [this](uint32_t a, uint32_t& v) {
      if (a == kUs1Csr) {
        v = 0;
        return true;
      }
      if (a == kAdcCdr6) {
        v = cmdLine ? 0x3A0u : 0x010u;
        return true;
      }
      return false;
    };
    bus.onWrite = [this](uint32_t a, uint32_t v) {
      if (a == kPioSodr && (v & kPinBtArm7Cmd)) armCmd = true;
      if (a == kPioCodr && (v & kPinBtArm7Cmd)) armCmd = false;
      if (a == kUs1Ptcr && (v & (1u << 9))) heldTx.clear();     // TXTDIS: the transfer is abandoned
      if (a == kUs1Ptcr && (v & 1u)) rxPdc = true;              // RXTEN
      if (a == kUs1Ptcr && (v & 2u)) rxPdc = false;             // RXTDIS
      if (a == kUs1Rncr && v != 0 && bus.regs[kUs1Rcr] == 0) {  // the next buffer starts at once
        bus.regs[kUs1Rpr] = bus.regs[kUs1Rnpr];
        bus.regs[kUs1Rcr] = v;
        bus.regs[kUs1Rncr] = 0;
      }
      if (a == kPioCodr && (v & kPinBtReset)) resetHeld = true;
      if (a == kPioSodr && (v & kPinBtReset) && resetHeld) {
        resetHeld = false;
        if (indicateReset) reply(0x14, {});  // RESET_INDICATION
      }
      if (a == kUs1Ptcr && (v & (1u << 8))) {  // TXTEN: TCR bytes from TPR, then TNCR from TNPR
        const uint8_t* p = bus.pointer(bus.regs[kUs1Tpr]);
        heldTx.assign(p, p + bus.regs[kUs1Tcr]);
        if (bus.regs[kUs1Tncr] != 0) {
          const uint8_t* q = bus.pointer(bus.regs[kUs1Tnpr]);
          heldTx.insert(heldTx.end(), q, q + bus.regs[kUs1Tncr]);
        }
        if (!holdTx) releaseTx();
      }
    };
  }
  // RTS as the USART drives it in hardware-handshaking mode.
  bool rtsHigh() {
    using namespace reg;
    const bool handshake = (bus.regs[kUs1Mr] & 0xFu) == 2u;
    return handshake && (!rxPdc || (bus.regs[kUs1Rcr] == 0 && bus.regs[kUs1Rncr] == 0));
  }
  // The module sends while RTS is low; each byte lands at RPR (the next buffer chained in at RCR 0).
  void deliver() {
    using namespace reg;
    while (!toArm.empty() && !rtsHigh()) {
      auto* p = const_cast<uint8_t*>(bus.pointer(bus.regs[kUs1Rpr]));
      *p = toArm.front();
      toArm.pop_front();
      ++bus.regs[kUs1Rpr];
      if (--bus.regs[kUs1Rcr] == 0 && bus.regs[kUs1Rncr] != 0) {
        bus.regs[kUs1Rpr] = bus.regs[kUs1Rnpr];
        bus.regs[kUs1Rcr] = bus.regs[kUs1Rncr];
        bus.regs[kUs1Rncr] = 0;
      }
    }
  }
  void releaseTx() {
    using namespace reg;
    const std::vector<uint8_t> bytes = std::move(heldTx);
    heldTx.clear();
    for (uint8_t b : bytes) received(b);
    bus.regs[kUs1Tcr] = 0;
    bus.regs[kUs1Tncr] = 0;
  }
  void reply(uint8_t code, std::vector<uint8_t> payload) {
    std::vector<uint8_t> f{static_cast<uint8_t>(payload.size() + 3), code};
    f.insert(f.end(), payload.begin(), payload.end());
    uint16_t sum = 0;
    for (uint8_t b : f) sum = static_cast<uint16_t>(sum + b);  // includes the length byte
    sum = static_cast<uint16_t>(0u - sum);
    f.push_back(static_cast<uint8_t>(sum >> 8));
    f.push_back(static_cast<uint8_t>(sum));
    toArm.insert(toArm.end(), f.begin(), f.end());
  }
  std::vector<uint8_t> partial;
  void received(uint8_t b) {
    if (armCmd) {
      fromArm.push_back(b);
      return;
    }
    partial.push_back(b);
    if (partial.size() < 2 || partial.size() < static_cast<size_t>(partial[0]) + 1) return;
    std::vector<uint8_t> f;
    f.swap(partial);
    uint16_t sum = 0;
    for (size_t i = 1; i + 2 < f.size(); ++i) sum = static_cast<uint16_t>(sum + f[i]);  // length excluded
    const uint16_t got = static_cast<uint16_t>((f[f.size() - 2] << 8) | f.back());
    if (static_cast<uint16_t>(sum + got) != 0) {
      badChecksum = true;
      return;
    }
    commands.push_back(f);
    const uint8_t code = f[1];
    if (code == 0x27 && answerAddress) reply(0x28, localAddress);   // GET_LOCAL_ADDR
    if (code == 0x03 && answerOpenPort) reply(0x1B, {0x01, 0x00});  // PORT_OPEN_RESULT: open
    if (code == 0x09 && f[2] == 1) reply(0x13, {0x01, 0x05});       // CONNECT_RESULT: ok, handle 5
    if (code == 0x0B && f[2] == 5) cmdLine = true;                  // OPEN_STREAM(5)
    if (code == 0x0A) pinAnswer.assign(f.begin() + 2, f.end() - 2);
  }
  void requestConnection() { reply(0x16, {1, 2, 3, 4, 5, 6, 0}); }
  bool sawCommand(uint8_t code) const {
    for (const auto& c : commands)
      if (c[1] == code) return true;
    return false;
  }
};

template <class Bt>
void runMs(Bc4& m, Bt& bt, uint32_t& now, uint32_t ms) {
  for (uint32_t i = 0; i < ms; ++i, ++now) {
    m.deliver();
    bt.poll(now);
  }
}

}  // namespace nxtmap::fw::test
