#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/drivers/BlueCoreFrame.hpp"
#include "firmware/drivers/ByteRing.hpp"
#include "firmware/drivers/UsartRxDma.hpp"

namespace nxtmap::fw {

namespace bc {
// The module's own address: GET_LOCAL_ADDR (no payload) -> GET_LOCAL_ADDR_RESULT (7 bytes: the 6-byte
// address, most significant first, then one more byte that LEGO's firmware keeps but never reads).
constexpr uint8_t kGetLocalAddr = 0x27, kGetLocalAddrResult = 0x28;
}  // namespace bc

// The Bluetooth link: USART1 at 460800 8N1 with RTS/CTS to the BlueCore module, and the module's
// command protocol up to data (stream) mode:
//   RESET low 100 ms -> wait RESET_INDICATION (or 5 s) -> GET_LOCAL_ADDR -> GET_LOCAL_ADDR_RESULT (the
//   module's 6-byte Bluetooth address, most significant byte first, kept for GET_DEVICE_INFO; no answer
//   within kReplyMs leaves it zeros) -> OPEN_PORT -> PORT_OPEN_RESULT ->
//   listen: REQUEST_PIN_CODE -> PIN_CODE "1234"; REQUEST_CONNECTION -> ACCEPT_CONNECTION(1) ->
//   CONNECT_RESULT(1, handle) -> OPEN_STREAM(handle) -> BC4 CMD line (ADC6 > 0x200) -> ARM7_CMD
//   (PA27) high = stream mode: from then on the UART carries the PC's byte stream, passed through
//   raw (readByte / write); the telegram framing (NXT 2-byte length) is the caller's.
//   The CMD line going low (link lost) -> the stream's unsent bytes dropped and the transmitter
//   stopped, then ARM7_CMD low (so no stream byte reaches the module as part of a command) -> OPEN_PORT
//   again (linkEpoch() counts it). A REQUEST_CONNECTION is taken while the port is being opened too:
//   the module only sends it with the port open (a PC may dial in before PORT_OPEN_RESULT arrives).
// Command-mode messages come back to back (36 bytes at most: 0.8 ms); a partial message that gets no
// byte for kMessageGapMs is noise (e.g. the tail of a message cut by the switch from stream mode) and
// the parser starts over at the next byte, so it never swallows the messages after it.
// Received bytes arrive through the USART1 receive PDC (UsartRxDma: with hardware handshaking the
// chip holds RTS high unless a PDC receive buffer is free) and are read from its buffers in the main
// loop; transmission uses the USART1 PDC from a transmit ring. poll() runs in the main loop.
// Bus: read(addr), write(addr, value), address(pointer) = the bus address a PDC takes.
template <class Bus>
class BlueCore {
 public:
  enum class State : uint8_t {
    Off,
    Resetting,
    WaitReset,
    GetAddress,
    OpenPort,
    Listening,
    Accepting,
    OpeningStream,
    Stream
  };
  static constexpr uint32_t kResetMs = 100, kResetWaitMs = 5000, kReplyMs = 500, kStreamWaitMs = 2000,
                            kMessageGapMs = 20;
  static constexpr uint16_t kCmdThreshold = 0x200;
  static constexpr uint8_t kPin[4] = {'1', '2', '3', '4'};

  explicit BlueCore(Bus& bus) : bus_(bus) {}

  void init(uint32_t mck, uint32_t nowMs) {
    using namespace reg;
    bus_.write(kPmcPcer, (1u << kIdUsart1) | (1u << kIdPioa) | (1u << kIdAdc));
    // Control pins: PA11 reset (low = held in reset), PA27 ARM7_CMD (low = command mode), PA31 CS high.
    bus_.write(kPioPer, kPinBtReset | kPinBtArm7Cmd | kPinBtCs);
    bus_.write(kPioPpudr, kPinBtArm7Cmd);
    bus_.write(kPioCodr, kPinBtReset | kPinBtArm7Cmd);
    bus_.write(kPioSodr, kPinBtCs);
    bus_.write(kPioOer, kPinBtReset | kPinBtArm7Cmd | kPinBtCs);
    // RXD1, TXD1, RTS1, CTS1 to USART1 (peripheral A). Never PA23 (SCK1): it is sensor port 1's SCL.
    const uint32_t uartPins = kPinBtRxd | kPinBtTxd | kPinBtRts | kPinBtCts;
    bus_.write(kPioPdr, uartPins);
    bus_.write(kPioAsr, uartPins);
    bus_.write(kUs1Cr, (1u << 2) | (1u << 3) | (1u << 5) | (1u << 7));  // RSTRX RSTTX RXDIS TXDIS
    bus_.write(kUs1Mr, 2u | (3u << 6) | (4u << 9) | (1u << 19));        // HW handshake, 8 bit, no parity, 1 stop, OVER
    bus_.write(kUs1Brgr, mck / 8 / 460800);
    bus_.write(kUs1Ptcr, (1u << 1) | (1u << 9));  // RX/TX PDC off
    bus_.write(kUs1Idr, ~0u);                     // polled: no USART interrupt
    rx_.start();
    bus_.write(kUs1Cr, (1u << 4) | (1u << 6));  // RXEN TXEN
    // ADC channel 6 reads the BC4 CMD line.
    bus_.write(kAdcCr, 1u);                                    // SWRST
    bus_.write(kAdcMr, (4u << 8) | (12u << 16) | (2u << 24));  // 5 MHz, 20 us startup, 600 ns S/H
    bus_.write(kAdcCher, 1u << 6);
    enter(State::Resetting, nowMs);
  }

  State state() const { return state_; }
  bool streaming() const { return state_ == State::Stream; }
  uint32_t badMessages() const { return parser_.badMessages(); }
  // The module's Bluetooth address, most significant byte first (zeros until it has answered).
  const uint8_t (&address() const)[6] { return address_; }

  // USART1 interrupt: none is enabled (reception is polled from the PDC buffers).
  void onInterrupt() {}

  // Main loop: runs the connection state machine (command mode: drains received bytes into the
  // command parser) and feeds the transmitter.
  void poll(uint32_t nowMs) {
    pumpTx();
    const uint16_t cmd = static_cast<uint16_t>(bus_.read(reg::kAdcCdr6) & 0x3FF);
    bus_.write(reg::kAdcCr, 2u);  // START the next conversion
    if (state_ == State::Stream) {
      if (cmd < kCmdThreshold) leaveStream(nowMs);
      return;
    }
    if (rx_.pending() != 0) {
      lastRxMs_ = nowMs;
    } else if (nowMs - lastRxMs_ >= kMessageGapMs) {
      parser_.reset();  // a partial message that stopped is noise
    }
    uint8_t b;
    while (rx_.pop(b)) {
      if (parser_.push(b)) onMessage(nowMs);
    }
    step(nowMs, cmd);
  }

  // Stream mode: the next byte from the PC.
  bool readByte(uint8_t& b) { return state_ == State::Stream && rx_.pop(b); }
  // Stream mode: queues n bytes for the PC, all or nothing; false if not streaming or no room.
  bool write(const uint8_t* bytes, uint16_t n) {
    if (state_ != State::Stream || tx_.space() < n) return false;
    for (uint16_t i = 0; i < n; ++i) tx_.push(bytes[i]);
    pumpTx();
    return true;
  }
  uint16_t txSpace() const { return tx_.space(); }
  // Received bytes wait in the PDC buffers.
  bool rxPending() const { return rx_.pending() != 0; }
  // Counts stream sessions that ended (the PC must be treated as gone).
  uint32_t linkEpoch() const { return linkEpoch_; }

 private:
  void enter(State s, uint32_t nowMs) {
    state_ = s;
    sinceMs_ = nowMs;
    sent_ = false;
  }
  // The link is gone (CMD line low): the PC's unread bytes and the bytes still queued for it are
  // dropped, the transmitter stops (its PDC's counters zeroed, both buffers; RSTTX abandons the byte
  // being shifted out), and only then ARM7_CMD
  // goes low: from here every byte to the module is a command again.
  void leaveStream(uint32_t nowMs) {
    using namespace reg;
    bus_.write(kUs1Ptcr, 1u << 9);  // TXTDIS
    bus_.write(kUs1Tcr, 0);         // the PDC keeps both counters: a stale next buffer (TNCR) would
    bus_.write(kUs1Tncr, 0);        // follow the next command with old stream bytes
    bus_.write(kUs1Cr, 1u << 3);    // RSTTX
    bus_.write(kUs1Cr, 1u << 6);    // TXEN
    tx_.clear();
    inFlight_ = 0;
    rx_.clear();
    parser_.reset();
    lastRxMs_ = nowMs;
    bus_.write(kPioCodr, kPinBtArm7Cmd);
    ++linkEpoch_;
    enter(State::OpenPort, nowMs);
  }
  void command(uint8_t code, const uint8_t* payload, uint8_t n) {
    uint8_t frame[kBcMaxPayload + 4];
    const uint8_t len = encodeBcCommand(code, payload, n, frame);
    for (uint8_t i = 0; i < len; ++i) tx_.push(frame[i]);
    pumpTx();
    sent_ = true;
  }
  void step(uint32_t nowMs, uint16_t cmd) {
    const uint32_t in = nowMs - sinceMs_;
    switch (state_) {
      case State::Off:
      case State::Listening:
      case State::Stream: return;
      case State::Resetting:
        bus_.write(reg::kPioCodr, reg::kPinBtReset | reg::kPinBtArm7Cmd);
        if (in >= kResetMs) {
          bus_.write(reg::kPioSodr, reg::kPinBtReset);
          parser_.reset();
          enter(State::WaitReset, nowMs);
        }
        return;
      case State::WaitReset:
        if (in >= kResetWaitMs) enter(State::GetAddress, nowMs);
        return;
      case State::GetAddress:
        if (!sent_) command(bc::kGetLocalAddr, nullptr, 0);
        if (in >= kReplyMs) enter(State::OpenPort, nowMs);
        return;
      case State::OpenPort:
        if (!sent_ || in >= kReplyMs) {
          command(bc::kOpenPort, nullptr, 0);
          sinceMs_ = nowMs;
        }
        return;
      case State::Accepting:
        if (in >= kReplyMs) enter(State::Listening, nowMs);
        return;
      case State::OpeningStream:
        if (cmd >= kCmdThreshold) {
          bus_.write(reg::kPioSodr, reg::kPinBtArm7Cmd);
          rx_.clear();
          enter(State::Stream, nowMs);
        } else if (in >= kStreamWaitMs) {
          enter(State::OpenPort, nowMs);
        }
        return;
    }
  }
  void onMessage(uint32_t nowMs) {
    const uint8_t code = parser_.code();
    const uint8_t* p = parser_.payload();
    const uint8_t n = parser_.payloadLength();
    if (code == bc::kResetIndication) {
      enter(State::GetAddress, nowMs);
    } else if (code == bc::kGetLocalAddrResult && n >= 6) {
      for (uint8_t i = 0; i < 6; ++i) address_[i] = p[i];
      if (state_ == State::GetAddress) enter(State::OpenPort, nowMs);
    } else if (code == bc::kPortOpenResult && state_ == State::OpenPort) {
      if (n >= 1 && (p[0] & 1u)) enter(State::Listening, nowMs);
    } else if (code == bc::kRequestPinCode && n >= 7) {
      uint8_t answer[7 + 16] = {};
      for (uint8_t i = 0; i < 7; ++i) answer[i] = p[i];
      for (uint8_t i = 0; i < 4; ++i) answer[7 + i] = kPin[i];
      command(bc::kPinCode, answer, sizeof(answer));
    } else if (code == bc::kRequestConnection && (state_ == State::Listening || state_ == State::OpenPort)) {
      const uint8_t yes = 1;
      command(bc::kAcceptConnection, &yes, 1);
      enter(State::Accepting, nowMs);
    } else if (code == bc::kConnectResult && state_ == State::Accepting) {
      if (n >= 2 && p[0] == 1) {
        const uint8_t handle = p[1];
        command(bc::kOpenStream, &handle, 1);
        enter(State::OpeningStream, nowMs);
      } else {
        enter(State::Listening, nowMs);
      }
    }
  }
  // Starts a PDC transfer of the ring's contiguous pending bytes when the previous one is over.
  // Every pending byte goes in one PDC transfer: the part that wraps round the ring as the next
  // buffer, so a telegram that crosses the ring's end still leaves as one burst (a PC that reads a
  // length and then the body in one read gets it whole). Done when both counters are 0.
  void pumpTx() {
    using namespace reg;
    if (inFlight_ > 0) {
      if (bus_.read(kUs1Tcr) != 0 || bus_.read(kUs1Tncr) != 0) return;
      tx_.drop(inFlight_);
      inFlight_ = 0;
    }
    const uint16_t n = tx_.contiguous();
    if (n == 0) return;
    const uint16_t wrapped = static_cast<uint16_t>(tx_.size() - n);
    inFlight_ = static_cast<uint16_t>(n + wrapped);
    compilerBarrier();  // the ring's bytes in RAM before the PDC reads them
    bus_.write(kUs1Tpr, bus_.address(tx_.tailPointer()));
    bus_.write(kUs1Tcr, n);
    if (wrapped > 0) {
      bus_.write(kUs1Tnpr, bus_.address(tx_.start()));
      bus_.write(kUs1Tncr, wrapped);
    }
    bus_.write(kUs1Ptcr, 1u << 8);  // TXTEN
  }

  Bus& bus_;
  UsartRxDma<Bus> rx_{bus_};
  ByteRing<512> tx_;
  BcParser parser_;
  uint32_t linkEpoch_ = 0;
  uint8_t address_[6] = {};
  uint16_t inFlight_ = 0;
  uint32_t sinceMs_ = 0;
  uint32_t lastRxMs_ = 0;  // last poll that found received bytes (command mode)
  bool sent_ = false;
  volatile State state_ = State::Off;
};

}  // namespace nxtmap::fw
