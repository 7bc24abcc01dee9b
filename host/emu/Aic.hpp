// Aic: the Advanced Interrupt Controller (0xFFFFF000). 32 sources with priority 0..7, an in-service
// stack for nesting, software set/clear (ISCR/ICCR, used as a soft IRQ on line 10), IVR/EOICR handshake.
// Sources are level lines polled from the peripheral models; edge-triggered sources latch rising edges.
// DCR (datasheet "Protect Mode" and "General Interrupt Mask"): with PROT an IVR read returns the vector
// but changes nothing (a debugger may read it); the write to IVR that must follow acknowledges the
// source read (pushes it in service, clears its edge); with GMSK neither nIRQ nor the wake-up is raised.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>
#include <functional>
#include <vector>

namespace nxtmap::emu {

class Aic : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFF000;
  static constexpr uint32_t kSize = 0x200;
  static constexpr int kIdSys = 1, kIdPioa = 2, kIdAdc = 4, kIdSpi = 5, kIdUs0 = 6, kIdUs1 = 7, kIdSsc = 8, kIdTwi = 9,
                       kIdPwm = 10, kIdUdp = 11;

  const char* name() const override { return "AIC"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override { return (off >= 0x120 && off <= 0x12C) || off == 0x138; }
  void setClock(Clock* clock) { clock_ = clock; }

  // A peripheral's interrupt line (true = asserting). Several lines may share one source (SYS).
  void connect(int id, std::function<bool()> line);
  // Samples the lines (edge latches); call after models advanced. The two queries below use the last
  // sample (the run loop samples once per stop); register reads sample afresh.
  void sample();
  // nIRQ: an enabled pending source above the current in-service priority.
  bool irqAsserted() { return !(dcr_ & kGmsk) && bestPending(false) >= 0; }
  // Any enabled pending source at all (wakes the processor clock even when CPSR.I masks it).
  bool wakeAsserted() { return !(dcr_ & kGmsk) && (pendingFrom(lastLevel_) & imr_) != 0; }
  uint32_t pending();  // IPR, sampled now
  uint64_t irqsTaken() const { return irqsTaken_; }

 private:
  static constexpr uint32_t kProt = 1, kGmsk = 2;
  uint32_t acknowledge(int id);  // pushes `id` in service, clears its edge; its vector
  int bestPending(bool fresh);   // highest-priority enabled pending source, -1 if none above the current level
  uint32_t pendingFrom(uint32_t level) const;
  bool edge(int id) const { return ((smr_[id] >> 5) & 1) != 0; }

  std::array<uint32_t, 32> smr_{};
  std::array<uint32_t, 32> svr_{};
  struct Line {
    int id;
    std::function<bool()> asserted;
  };
  std::vector<Line> lines_;
  uint32_t imr_ = 0;
  uint32_t soft_ = 0;  // set by ISCR, cleared by ICCR (and by IVR for edge sources)
  uint32_t edgeLatch_ = 0;
  uint32_t edgeMask_ = 0;  // sources configured edge-triggered (SMR SRCTYPE bit 5)
  uint32_t lastLevel_ = 0;
  uint32_t spu_ = 0;
  uint32_t dcr_ = 0;
  uint32_t isr_ = 0;
  int protectRead_ = -1;  // protect mode: the source the last IVR read returned, acknowledged by the IVR write
  struct Level {
    int id;
    int prio;
  };
  std::vector<Level> inService_;
  uint64_t irqsTaken_ = 0;
  Clock* clock_ = nullptr;
};

}  // namespace nxtmap::emu
