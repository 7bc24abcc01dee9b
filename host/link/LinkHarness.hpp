// LinkHarness: the stand-in brick and a PC Session joined by two LossyPipes, on a virtual
// millisecond clock, with the byte rate of the NXT's radio UART (460800 baud, 8N1: 46.08
// bytes per ms). For end-to-end tests and the link benchmark: deterministic for a seed.
#pragma once
#include <cstdint>
#include <deque>
#include <functional>

#include "host/link/LossyPipe.hpp"
#include "host/link/Session.hpp"
#include "host/link/SimBrick.hpp"

namespace nxtmap::link {

struct HarnessConfig {
  uint32_t baud = 460800;
  LossConfig toPc;
  LossConfig toBrick;
};

class LinkHarness {
 public:
  LinkHarness(SimBrick& brick, Session& pc, const HarnessConfig& config);

  // Advances the clock by one millisecond: the brick steps, bytes travel, the PC answers.
  void tick();
  // Runs until `done()` or `maxMs` more milliseconds; returns whether done() became true.
  bool runUntil(const std::function<bool()>& done, uint32_t maxMs);
  // Breaks the connection: bytes in flight are lost, both ends are told, the link comes back
  // after `downMs` (nothing passes meanwhile).
  void disconnect(uint32_t downMs);

  uint32_t nowMs() const { return now_; }
  const LossyPipe& toPc() const { return toPc_; }
  const LossyPipe& toBrick() const { return toBrick_; }
  uint64_t wireBytesToPc() const { return wireToPc_; }

 private:
  SimBrick& brick_;
  Session& pc_;
  HarnessConfig config_;
  LossyPipe toPc_, toBrick_;
  std::deque<uint8_t> pcInbox_, brickInbox_;  // bytes on the wire, waiting for the UART rate
  double creditToPc_ = 0, creditToBrick_ = 0;
  uint32_t now_ = 0;
  uint32_t upAtMs_ = 0;
  uint64_t wireToPc_ = 0;
};

}  // namespace nxtmap::link
