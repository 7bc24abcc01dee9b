#pragma once
#include <cstdint>

#include "common/protocol/BrickLink.hpp"
#include "firmware/app/ModeMachine.hpp"
#include "firmware/app/Screen.hpp"
#include "firmware/board/Mmio.hpp"
#include "firmware/drivers/AvrLink.hpp"
#include "firmware/drivers/BlueCore.hpp"
#include "firmware/drivers/Lcd.hpp"
#include "firmware/drivers/MotorSafety.hpp"

namespace nxtmap::fw {

// The LCD while the brick runs: the room map on the left (redrawn one 8-row band per main-loop
// pass when it changed, at most every kMapRedrawMs; only the robot's blinking pixel in between)
// and a status column on the right: mode, battery, Bluetooth state, link, the run's cells moved
// (C) and sensor requests (R), the room number, and why the motors stopped after a trip. Reads
// the parts it shows (BrickApp's); owns nothing but the drawing schedule.
class StatusScreen {
 public:
  static constexpr uint32_t kBlinkMs = 500;      // robot pixel blink and status refresh
  static constexpr uint32_t kMapRedrawMs = 500;  // the map is redrawn at most this often, and only when it changed

  StatusScreen(Screen::Frame& frame, Lcd<Mmio>& lcd, const ModeMachine& modes, const BlueCore<Mmio>& bt,
               const protocol::BrickLink& link, const AvrLink<Mmio>& avr, const MotorSafety& safety)
      : screen_(frame), lcd_(lcd), modes_(modes), bt_(bt), link_(link), avr_(avr), safety_(safety) {}
  StatusScreen(const StatusScreen&) = delete;
  StatusScreen& operator=(const StatusScreen&) = delete;

  void clear() { screen_.clear(); }
  // Every kBlinkMs: the status column, and the map redraw started or the robot pixel blinked.
  void draw(uint32_t nowMs);
  // The next band of a map redraw, if one is under way (one per main-loop pass).
  void drawMapPages();
  // The whole screen: a failed check's file, line and condition.
  void showCheckFailed(const char* file, int line, const char* what);

 private:
  void drawMode(int x);
  void drawBattery(int x);
  void drawLinks(int x);
  void drawCounters(int x);
  void drawRoom(int x);
  void drawTrip(int x);

  Screen screen_;
  Lcd<Mmio>& lcd_;
  const ModeMachine& modes_;
  const BlueCore<Mmio>& bt_;
  const protocol::BrickLink& link_;
  const AvrLink<Mmio>& avr_;
  const MotorSafety& safety_;
  uint32_t lastDrawMs_ = 0, lastMapDrawMs_ = 0;
  uint32_t mapDrawn_ = 0;  // ModeMachine::mapVersion() of the last map redraw (0: none yet)
  int8_t mapPage_ = -1;    // next map band to draw, -1 = none pending
  bool blink_ = false;
};

}  // namespace nxtmap::fw
