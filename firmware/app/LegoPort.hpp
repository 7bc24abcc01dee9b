#pragma once
#include <cstdint>

#include "common/protocol/LegoBrick.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/ModeMachine.hpp"
#include "firmware/board/Mmio.hpp"
#include "firmware/drivers/BlueCore.hpp"
#include "firmware/drivers/Speaker.hpp"

namespace nxtmap::fw {

// LEGO's direct commands as the brick carries them out (the BrickLink's LegoBrick): the outputs
// through the ModeMachine (obeyed while the robot rests, through the same MotorSafety), the
// ultrasonic ports' last readings from the ActionRunner, tones on the Speaker, the Bluetooth address
// the BlueCore module reported; free flash from the linker's symbols. All parts are BrickApp's.
class LegoPort final : public protocol::LegoBrick {
 public:
  LegoPort(ModeMachine& modes, const ActionRunner& runner, Speaker<Mmio>& speaker, const BlueCore<Mmio>& bt,
           uint32_t mck)
      : modes_(modes), runner_(runner), speaker_(speaker), bt_(bt), mck_(mck) {}

  protocol::LegoOutputState output(uint8_t port) const override { return modes_.output(port); }
  // Every port holds an ultrasonic sensor: LEGO's LOW_SPEED_9V type, the reading in cm as the
  // scaled value (255: no echo), valid once the port has been read.
  protocol::LegoInputValues input(uint8_t port) const override {
    protocol::LegoInputValues v;
    v.sensorType = protocol::kLegoLowSpeed9V;
    uint8_t cm = 0;
    v.valid = runner_.lastReading(port, cm);
    v.raw = v.normalized = cm;
    v.scaled = v.calibrated = cm;
    return v;
  }
  uint8_t setOutput(const protocol::LegoOutputCommand& c) override { return modes_.setOutput(c); }
  uint8_t resetPosition(uint8_t port, bool relative) override { return modes_.resetPosition(port, relative); }
  void playTone(uint16_t hz, uint16_t ms) override { speaker_.play(mck_, hz, ms); }
  void stopSound() override { speaker_.stop(); }
  void address(uint8_t (&a)[6]) const override {
    for (uint8_t i = 0; i < 6; ++i) a[i] = bt_.address()[i];
  }
  // Flash above the image (the flash build: 256 KiB less the code and .data image); the RAM-run
  // image lives in RAM and knows nothing of what the flash holds: 0.
  uint32_t freeFlashBytes() const override;

 private:
  ModeMachine& modes_;
  const ActionRunner& runner_;
  Speaker<Mmio>& speaker_;
  const BlueCore<Mmio>& bt_;
  uint32_t mck_;
};

// The linker script's end of the flashed image (nxt-sections.ld: the .data image's load address
// and size) against the flash's 256 KiB at 0x100000.
extern "C" char __data_load[], __data_start[], __data_end[];

inline uint32_t LegoPort::freeFlashBytes() const {
#ifdef NXTMAP_RAM_RUN
  return 0;
#else
  constexpr uint32_t kFlashBase = 0x100000, kFlashBytes = 256 * 1024;
  const uint32_t end = Mmio::address(__data_load) + static_cast<uint32_t>(__data_end - __data_start);
  return end >= kFlashBase + kFlashBytes ? 0 : kFlashBase + kFlashBytes - end;
#endif
}

}  // namespace nxtmap::fw
