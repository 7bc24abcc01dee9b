#pragma once
#include <cstdint>

#include "common/protocol/BrickLink.hpp"
#include "firmware/app/ModeMachine.hpp"
#include "firmware/board/Mmio.hpp"
#include "firmware/drivers/AvrLink.hpp"
#include "firmware/drivers/BlueCore.hpp"

namespace nxtmap::fw {

// The radio: BlueCore stream bytes in and out of the BrickLink, the PC's commands to the mode
// machine, and the brick's frames (status, map changes, answers) out at a pace the main loop can
// afford. All parts are BrickApp's; the service keeps only the transmit pacing.
class RadioService {
 public:
  // Frames go out one per main-loop pass while the link has some, then after a pause of this long.
  static constexpr uint32_t kPeriodMs = 50;

  RadioService(BlueCore<Mmio>& bt, protocol::BrickLink& link, ModeMachine& modes, const AvrLink<Mmio>& avr)
      : bt_(bt), link_(link), modes_(modes), avr_(avr) {}
  RadioService(const RadioService&) = delete;
  RadioService& operator=(const RadioService&) = delete;

  // One main-loop pass at `nowMs`: the BlueCore's state machine, every byte received, every
  // command complete, and at most one frame sent.
  void serve(uint32_t nowMs);

 private:
  void receive(uint32_t nowMs);
  void transmit(uint32_t nowMs);

  BlueCore<Mmio>& bt_;
  protocol::BrickLink& link_;
  ModeMachine& modes_;
  const AvrLink<Mmio>& avr_;  // the battery voltage for the reports
  uint32_t lastSentMs_ = 0;
  bool burst_ = false;  // the last transmit produced a frame: ask again next pass
};

}  // namespace nxtmap::fw
