// TimerCounter: the TC block (0xFFFA0000, channels 0..2 at +0x40 each, IDs 12..14). Counting from
// MCK/2../1024; RC compare (CPCS) with the RC trigger (capture CPCTRG or waveform WAVSEL=10) restarting
// the count; the 16-bit counter's overflow (COVFS); the counter value is computed from the clock.
// Capture mode (WAVE = 0), as LEGO's tachometers use it: the TIOA input (TIOA0/1/2 = PA0/PA15/PA26, the
// tacho pulse pins of motors C, A, B) loads RA on the LDRA edge and RB on the LDRB edge once RA was loaded
// since the last trigger (LDRAS/LDRBS; a load over an unread one sets LOVRS); with ABETRG the TIOA edge
// chosen by ETRGEDG is the external trigger (ETRGS) and restarts the count; LDBSTOP/LDBDIS stop or
// disable the clock at an RB load; SR's MTIOA is the TIOA level. Status bits clear when SR is read.
// Not modelled: external clocks XC0..2, TIOB as an input or trigger, waveform outputs, BURST.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>

namespace nxtmap::emu {

class TimerCounter : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFA0000;
  static constexpr uint32_t kSize = 0x100;
  static constexpr std::array<int, 3> kTioaPin{0, 15, 26};  // PIOA pin of TIOA0..2
  static constexpr uint32_t kCovfs = 1u << 0, kLovrs = 1u << 1, kCpcs = 1u << 4, kLdras = 1u << 5, kLdrbs = 1u << 6,
                            kEtrgs = 1u << 7, kClksta = 1u << 16, kMtioa = 1u << 17;
  explicit TimerCounter(Clock& clock) : clock_(clock) {}

  const char* name() const override { return "TC"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override {
    const uint32_t r = off % 0x40;
    return off >= 0xC0 || (r != 0x04 && r != 0x14 && r != 0x18);
  }
  uint64_t nextEventAt() const override;
  bool irqLine(int channel) const;
  // The TIOA input of a channel now at `level` (an edge when it differs from the last level given).
  void setTioa(int channel, bool level);
  // The PIOA levels (every pin): each channel's TIOA pin.
  void pinsChanged(uint32_t levels);

 private:
  struct Channel {
    uint32_t cmr = 0, ra = 0, rb = 0, rc = 0, imr = 0;
    bool running = false;
    uint64_t start = 0;          // clock when the count last restarted from 0
    uint64_t comparesRead = 0;   // RC compares already reported by an SR read
    uint64_t overflowsRead = 0;  // counter wraps already reported by an SR read
    uint32_t latched = 0;        // LOVRS, LDRAS, LDRBS, ETRGS since the last SR read
    bool tioa = true;            // released pins read high
    bool raLoaded = false;       // RA loaded since the last trigger or RB load
    bool raUnread = false, rbUnread = false;
  };
  uint64_t divider(const Channel& c) const;
  bool rcTrigger(const Channel& c) const;
  uint64_t compares(const Channel& c) const;   // RC compares since start
  uint64_t overflows(const Channel& c) const;  // counter wraps since start
  uint32_t counter(const Channel& c) const;
  uint32_t status(const Channel& c) const;
  void restart(Channel& c);
  void capture(Channel& c, bool rising);

  Clock& clock_;
  std::array<Channel, 3> ch_{};
};

}  // namespace nxtmap::emu
