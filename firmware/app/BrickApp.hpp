#pragma once
#include <cstdint>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/explore/PropagationExplorer.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/BrickConfig.hpp"
#include "firmware/app/RadioSeam.hpp"
#include "firmware/app/Screen.hpp"
#include "firmware/board/Aic.hpp"
#include "firmware/board/Mmio.hpp"
#include "firmware/drivers/AvrLink.hpp"
#include "firmware/drivers/BlueCore.hpp"
#include "firmware/drivers/Lcd.hpp"
#include "firmware/drivers/MotorSafety.hpp"
#include "firmware/drivers/SensorPortPins.hpp"
#include "firmware/drivers/TachoDecoder.hpp"

namespace nxtmap::fw {

// The brick application: owns every driver and the explorer, runs the main loop, and serves the
// interrupts (each ISR in main.cpp calls one on*() member). One static instance.
class BrickApp {
 public:
  enum class Mode : uint8_t { Idle, Exploring, Done, Fault };
  enum class Strategy : uint8_t { Propagation, Frontier };

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

  // A failed NXTMAP_CHECK: motors off, reason on the LCD, wait forever (the tick keeps the AVR
  // link alive so the motors stay stopped).
  [[noreturn]] void checkFailed(const char* file, int line, const char* what);

  // Commands (from the buttons or the radio).
  void startExploring(Strategy s);
  void stop();
  void newRoom();

  Mode mode() const { return mode_; }
  const Explorer* explorer() const { return explorer_; }

 private:
  void loopOnce();
  void driveExplorer(uint32_t now);
  void driveMotors();
  void readButtons(uint32_t now);
  void startSonarClock();
  void draw(uint32_t now);
  ActionRunner::Wheels wheels() const;
  Action feed(const Event& e);

  Mmio bus_{};
  BrickConfig config_{};
  Aic<Mmio> aic_{bus_};
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
  RadioSeam radio_{};
  Screen::Frame frame_ = {};
  Lcd<Mmio> lcd_{bus_, frame_};
  Screen screen_{frame_};

  BrickExplorerStorage storage_{};
  MapLayers map_;
  TravelPlanner planner_;
  ExplorerConfig explorerConfig_;
  alignas(PropagationExplorer) alignas(FrontierExplorer) uint8_t explorerBuf_[
      sizeof(PropagationExplorer) > sizeof(FrontierExplorer) ? sizeof(PropagationExplorer)
                                                             : sizeof(FrontierExplorer)];
  Explorer* explorer_ = nullptr;
  ActionRunner runner_;

  volatile uint32_t ms_ = 0;
  Mode mode_ = Mode::Idle;
  Button lastButton_ = Button::None;
  Button candidate_ = Button::None;
  uint32_t candidateSince_ = 0;
  uint32_t lastDrawMs_ = 0;
  bool blink_ = false;
};

}  // namespace nxtmap::fw
