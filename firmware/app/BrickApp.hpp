#pragma once
#include <cstdint>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/explore/PropagationExplorer.hpp"
#include "common/motion/Pilot.hpp"
#include "common/protocol/BrickLink.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/BrickConfig.hpp"
#include "firmware/app/PathFollower.hpp"
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

#ifdef NXTMAP_RAM_RUN
// The RAM-run image (libnxt fwexec) keeps its code in the same 56 KiB as its data: a 64 x 32 grid.
using AppExplorerStorage = ExplorerStorage<64, 32, 512>;
#else
using AppExplorerStorage = BrickExplorerStorage;
static_assert(AppExplorerStorage::kWidth() == 64 && AppExplorerStorage::kHeight() == 64,
              "the brick's RAM budget (make size) is measured with a 64 x 64-cell room grid");
#endif

// The brick application: owns every driver, the explorer with its pilot, and the radio link;
// runs the main loop and serves the interrupts (each ISR in main.cpp calls one on*() member).
// Commands come from the buttons (Enter: explore with the published method, Right: explore with
// the frontier explorer, Exit: stop, Left: new room) and from the PC (protocol::Command).
class BrickApp {
 public:
  enum class Strategy : uint8_t { Propagation, Frontier };
  using Mode = protocol::BrickMode;

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

 private:
  void loopOnce();
  void serveRadio(uint32_t now);
  void carryOut(const protocol::Command& c, uint32_t now);
  void startExploring(Strategy s, uint32_t now);
  void followPath(const protocol::PathMsg& path, uint32_t now);
  void takeMapChunk(const protocol::MapChunkMsg& chunk);
  // Stops and stands the robot at `p` (no run holds the pose until the next Explore).
  void restAt(const Pose& p);
  void stop();
  void newRoom();
  void driveRobot(uint32_t now);
  void driveMotors();
  void readButtons(uint32_t now);
  void startSonarClock();
  void draw(uint32_t now);
  void drawMapPages();
  Pose pose() const;
  protocol::BrickReport report() const;
  ActionRunner::Wheels wheels() const;

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
  Screen::Frame frame_ = {};
  Lcd<Mmio> lcd_{bus_, frame_};
  Screen screen_{frame_};

  AppExplorerStorage storage_{};
  MapLayers map_;
  TravelPlanner planner_;
  ExplorerConfig explorerConfig_;
  uint8_t shadow_[packedBytes(AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight(), 2)] = {};
  protocol::BrickLink link_;
  alignas(PropagationExplorer) alignas(FrontierExplorer) uint8_t
      explorerBuf_[sizeof(PropagationExplorer) > sizeof(FrontierExplorer) ? sizeof(PropagationExplorer)
                                                                          : sizeof(FrontierExplorer)];
  alignas(Pilot) uint8_t pilotBuf_[sizeof(Pilot)];
  Explorer* explorer_ = nullptr;
  Pilot* pilot_ = nullptr;
  ActionRunner runner_;
  PathFollower follower_{};
  DriveAction pending_{};  // the action being carried out
  Pose restPose_{};        // where the robot stands when neither the explorer nor a path moved it last
  bool poseFromPath_ = false;

  volatile uint32_t ms_ = 0;
  Mode mode_ = Mode::Idle;
  uint16_t roomId_ = 0;
  Button lastButton_ = Button::None;
  Button candidate_ = Button::None;
  uint32_t candidateSince_ = 0;
  uint32_t lastDrawMs_ = 0, lastMapDrawMs_ = 0, lastRadioMs_ = 0;
  bool radioBurst_ = false;  // the last transmit produced a frame: ask again next pass
  bool mapDirty_ = true;
  int8_t mapPage_ = -1;  // next map band to draw, -1 = none pending
  bool blink_ = false;
};

}  // namespace nxtmap::fw
