#pragma once
#include <cstdint>

#include "common/explore/ExplorerStack.hpp"
#include "common/explore/ExplorerStorage.hpp"
#include "common/house/HouseBrick.hpp"
#include "common/house/RoomConfinement.hpp"
#include "common/protocol/BrickLink.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/BrickConfig.hpp"
#include "firmware/app/EventBeeper.hpp"
#include "firmware/app/FlashWheelStore.hpp"
#include "firmware/app/LegoPort.hpp"
#include "firmware/app/ModeMachine.hpp"
#include "firmware/app/RadioService.hpp"
#include "firmware/app/Screen.hpp"
#include "firmware/app/StatusScreen.hpp"
#include "firmware/board/Aic.hpp"
#include "firmware/board/Mmio.hpp"
#include "firmware/board/PioInputs.hpp"
#include "firmware/board/Pmc.hpp"
#include "firmware/board/SystemTimer.hpp"
#include "firmware/board/TimerCounter.hpp"
#include "firmware/drivers/AvrLink.hpp"
#include "firmware/drivers/BlueCore.hpp"
#include "firmware/drivers/Lcd.hpp"
#include "firmware/drivers/MotorSafety.hpp"
#include "firmware/drivers/SensorPortPins.hpp"
#include "firmware/drivers/Speaker.hpp"
#include "firmware/drivers/TachoDecoder.hpp"

namespace nxtmap::fw {

#ifdef NXTMAP_RAM_RUN
// The RAM-run image (libnxt fwexec) keeps its code in the same 56 KiB as its data: a 32 x 32 grid
// (6.4 m square at 20 cm cells; 64 x 32 until the LEGO command set took its code's place), and a
// travel-search queue of 96 states (a search over the published rooms on a 32 x 32 grid held at most 74).
using AppExplorerStorage = ExplorerStorage<32, 32, 96>;
#else
using AppExplorerStorage = BrickExplorerStorage;
static_assert(AppExplorerStorage::kWidth() == 64 && AppExplorerStorage::kHeight() == 64,
              "the brick's RAM budget (make size) is measured with a 64 x 64-cell room grid");
#endif

// The brick application: owns every driver, the explorer (ExplorerStack over storage_), the radio
// link and the three parts that use them (ModeMachine: what the robot does; RadioService: the PC;
// StatusScreen: the LCD); brings the board up, runs the main loop and serves the interrupts (each
// ISR in main.cpp calls one on*() member).
class BrickApp {
 public:
  BrickApp();
  BrickApp(const BrickApp&) = delete;
  BrickApp& operator=(const BrickApp&) = delete;

  // Brings up the peripherals and the interrupts; then run() never returns.
  void init();
  [[noreturn]] void run();

  // Interrupt entry points.
  void onSystem();
  void onPio();
  void onTwi();
  void onUsart1();
  void onTc0();
  void onSsc();

  // A failed NXTMAP_CHECK: motors off, reason on the LCD, wait forever (the tick keeps the AVR
  // link alive so the motors stay stopped).
  [[noreturn]] void checkFailed(const char* file, int line, const char* what);

 private:
  void initTachos();
  void initSensorPorts();
  void initAvr();
  void installInterrupts();
  void loopOnce();
  void guardMotors(uint32_t nowMs);
  void startSonarClock();
  WheelStore* wheelStore() {
#ifdef NXTMAP_RAM_RUN
    return nullptr;  // the RAM-run image learns no wheels
#else
    return &wheels_;
#endif
  }
  HouseBrick* houseBrick() {
#ifdef NXTMAP_RAM_RUN
    return nullptr;
#else
    return &house_;
#endif
  }

  Mmio bus_{};
  BrickConfig config_{};
  Aic<Mmio> aic_{bus_};
  Pmc<Mmio> pmc_{bus_};
  SystemTimer<Mmio> timer_{bus_};
  PioInputs<Mmio> pio_{bus_};
  TimerCounter<Mmio> sonarClock_{bus_};  // the soft I2C bit clock, running only during a transaction
  AvrLink<Mmio> avr_{bus_};
  TachoDecoder tacho_;
  SoftI2c i2c_{};
  SensorPortPins<Mmio> ports_[4];
  volatile uint8_t i2cPort_ = 0;
  volatile bool sonarClockOn_ = false;
  SonarSequencer sonar_{i2c_};
  MotionController motion_{};
  MotorSafety safety_{};
  BlueCore<Mmio> bt_{bus_};
  Screen::Frame frame_ = {};
  Lcd<Mmio> lcd_{bus_, frame_};
  Speaker<Mmio> speaker_{bus_};

  AppExplorerStorage storage_{};
  ExplorerStack stack_;
#ifndef NXTMAP_RAM_RUN
  // Mapping a house: the confinement's flood bits (one per cell of the room grid) and the house
  // commands over the one stack (ModeMachine::houseCommand). Not in the RAM-run image (no room).
  uint8_t reach_[packedBytes(AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight(), 1)] = {};
  RoomConfinement confinement_;
  HouseBrick house_;
#endif
  uint8_t shadow_[packedBytes(AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight(), 2)] = {};
  protocol::BrickLink link_;
  ActionRunner runner_;
#ifndef NXTMAP_RAM_RUN
  FlashWheelStore<Mmio> wheels_{FlashPage<Mmio>{bus_, nxtmapFlashCommand}};  // what the runs learnt of the wheels
#endif
  ModeMachine modes_;
  EventBeeper beeper_;  // short tones on the robot's own events
  LegoPort lego_;       // LEGO's direct commands on the outputs and sensors (attached to link_)
  RadioService radio_;
  StatusScreen status_;

  volatile uint32_t ms_ = 0;
};

}  // namespace nxtmap::fw
