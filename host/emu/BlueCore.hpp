// BlueCore: the BC4 Bluetooth module behind USART1, running LEGO's command protocol (nxt-hardware.md 6).
// Command mode (ARM7_CMD = PA27 low): frames [len][cmd][payload][csum BE], TX checksum over cmd+payload,
// RX checksum including the length byte. After RESET (PA11) rises it sends RESET_INDICATION; it answers the
// usual queries; a PC connecting on the LinkEndpoint while the port is open raises REQUEST_CONNECTION;
// ACCEPT_CONNECTION -> CONNECT_RESULT; LOOKUP_NAME of the connected PC -> LOOKUP_NAME_RESULT (its name and
// class), ADD_DEVICE -> LIST_RESULT success (LEGO's firmware does both before it opens the stream);
// OPEN_STREAM -> the CMD signal (ADC channel 6) goes high; then with PA27 high bytes pass through
// unchanged both ways (stream mode).
// The ARM selects the mode with ARM7_CMD (PA27): high = data, low = command. In data mode the ARM's bytes
// are stream data (lost when no stream is open) and only the PC's bytes reach it; in command mode only
// the module's messages do. So when the PC hangs up (the CMD signal drops, CLOSE_CONNECTION_RESULT is
// queued) the message waits until the ARM has lowered ARM7_CMD, and the ARM's last stream bytes are
// never taken for a command. The PC's bytes not yet delivered go with the link.
// Flow control: no byte is started towards the ARM while the ARM's RTS (the module's CTS) is high.
// Input bound: at most kPcInputBytes from the PC wait here (the module's buffer plus the radio's
// window); beyond that the transport is not read, so its own flow control holds the PC back.
// Output in bursts: the ARM's stream bytes go to the PC as one radio packet each time its UART falls
// quiet for kBurstGapCycles (the end of a PDC transmit buffer: the USART shifts a buffer's bytes back to
// back) or kMaxBurstBytes have gathered, never byte by byte, so a PC that reads a telegram's length and
// then its body in one read gets it whole.
#pragma once

#include "host/emu/IoDevice.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/emu/Pioa.hpp"
#include "host/emu/SerialPeer.hpp"

#include <deque>
#include <string>
#include <vector>

namespace nxtmap::emu {

class BlueCore : public SerialPeer, public IoDevice {
 public:
  static constexpr int kResetPin = 11, kArmCmdPin = 27;
  BlueCore(Clock& clock, Pioa& pio, LinkEndpoint* link) : clock_(clock), pio_(pio), link_(link) {}

  // SerialPeer
  void fromArm(uint8_t byte) override;
  bool hasByteForArm() const override;
  uint8_t takeByteForArm() override;
  void armRts(bool high) override { rtsHigh_ = high; }  // CTS: high = hold back

  // Time source (not on the bus): polls the PC side every millisecond, boot delay after reset.
  const char* name() const override { return "BC4"; }
  bool read(uint32_t, uint32_t&) override { return false; }
  bool write(uint32_t, uint32_t) override { return false; }
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;

  bool cmdSignal() const { return streamOpen_; }  // BC4 CMD line (ADC 6): high = stream open
  bool streaming() const { return streamOpen_ && pio_.level(kArmCmdPin); }
  uint64_t commandsSeen() const { return commands_; }
  uint64_t badFrames() const { return bad_; }
  const std::vector<uint8_t>& unknownCommands() const { return unknown_; }
  bool portOpen() const { return portOpen_; }
  bool connected() const { return connected_; }
  uint64_t bytesToPc() const { return toPc_; }
  uint64_t bytesFromPc() const { return fromPc_; }
  static constexpr size_t kPcInputBytes = 4096;       // most bytes from the PC held here
  size_t pcBuffered() const { return pcIn_.size(); }  // 0..kPcInputBytes
  // A quiet UART for 4 byte times at 460800 baud (87 us) ends a burst; a burst holds at most 1 KiB.
  static constexpr uint64_t kBurstGapCycles = kMckHz / 1000000 * 87;
  static constexpr size_t kMaxBurstBytes = 1024;
  uint64_t burstsToPc() const { return bursts_; }

 private:
  void command(const std::vector<uint8_t>& f);  // [cmd][payload...] of a checked frame
  void reply(uint8_t cmd, const std::vector<uint8_t>& payload);
  void lookUpName(const std::vector<uint8_t>& f);
  void pollLink();
  void flushBurst();                                        // hands the gathered stream bytes to the PC in one send
  bool dataMode() const { return pio_.level(kArmCmdPin); }  // ARM7_CMD high

  Clock& clock_;
  Pioa& pio_;
  LinkEndpoint* link_;
  bool running_ = false;        // RESET released
  bool rtsHigh_ = false;        // the ARM's RTS: while high no byte is started towards the ARM
  uint64_t bootAt_ = kNever;    // RESET_INDICATION due
  std::vector<uint8_t> frame_;  // command-mode bytes from the ARM being assembled
  std::deque<uint8_t> toArm_;
  std::deque<uint8_t> pcIn_;       // stream bytes waiting for the ARM, at most kPcInputBytes
  std::vector<uint8_t> burst_;     // stream bytes from the ARM not yet sent, at most kMaxBurstBytes
  uint64_t burstEndsAt_ = kNever;  // when the UART has been quiet long enough to send burst_
  bool portOpen_ = false, requested_ = false, connected_ = false, streamOpen_ = false;
  bool pcWasConnected_ = false;
  bool announced_ = false;  // REQUEST_CONNECTION sent for the current PC connection
  uint64_t nextPoll_ = 0;
  uint64_t commands_ = 0, bad_ = 0, toPc_ = 0, fromPc_ = 0, bursts_ = 0;
  std::vector<uint8_t> unknown_;
};

}  // namespace nxtmap::emu
