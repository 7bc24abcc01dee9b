#include "firmware/app/StatusScreen.hpp"

#include "common/check/Check.hpp"

namespace nxtmap::fw {
namespace {
// Status lines (top pixel row of each) in the right-hand column.
constexpr int kModeY = 0, kBatteryY = 7, kBluetoothY = 14, kLinkY = 21, kCellsY = 30, kRequestsY = 37, kRoomY = 44,
              kTripY = 52;
}  // namespace

void StatusScreen::draw(uint32_t nowMs) {
  if (nowMs - lastDrawMs_ < kBlinkMs) return;
  lastDrawMs_ = nowMs;
  blink_ = !blink_;
  const bool mapChanged = modes_.mapVersion() != mapDrawn_;
  if (mapChanged && mapPage_ < 0 && nowMs - lastMapDrawMs_ >= kMapRedrawMs) {
    mapDrawn_ = modes_.mapVersion();
    lastMapDrawMs_ = nowMs;
    mapPage_ = 0;  // drawMapPages() draws one band per loop pass
  } else if (mapPage_ < 0) {
    screen_.drawRobot(modes_.grid(), modes_.pose().cell, blink_);
  }
  const int x = Screen::kTextX;
  drawMode(x);
  drawBattery(x);
  drawLinks(x);
  drawCounters(x);
  drawRoom(x);
  drawTrip(x);
  lcd_.refresh();
}

void StatusScreen::drawMode(int x) {
  static const char* const kModes[] = {"IDLE", "MAP", "PATH", "DONE", "STOP"};
  screen_.clearLine(kModeY);
  screen_.text(x, kModeY, kModes[static_cast<int>(modes_.mode())]);
}

void StatusScreen::drawBattery(int x) {
  screen_.clearLine(kBatteryY);
  const uint32_t mv = batteryMillivolts(avr_.status().batteryRaw);
  int cx = screen_.number(x, kBatteryY, mv / 1000);
  cx = screen_.text(cx, kBatteryY, ".");
  cx = screen_.number(cx, kBatteryY, (mv / 100) % 10);
  screen_.text(cx, kBatteryY, "V");
}

void StatusScreen::drawLinks(int x) {
  static const char* const kBt[] = {"BT OFF",  "BT RST", "BT RST",  "BT ADDR", "BT PORT",
                                    "BT LIST", "BT ACC", "BT OPEN", "BT LINK"};
  screen_.clearLine(kBluetoothY);
  screen_.text(x, kBluetoothY, kBt[static_cast<int>(bt_.state())]);
  screen_.clearLine(kLinkY);
  screen_.text(x, kLinkY, link_.connected() ? "PC OK" : (avr_.up() ? "AVR OK" : "AVR --"));
}

void StatusScreen::drawCounters(int x) {
  if (!modes_.hasRun()) return;
  const Counters c = modes_.counters();
  screen_.clearLine(kCellsY);
  screen_.text(screen_.number(x, kCellsY, c.cellsMoved), kCellsY, " C");
  screen_.clearLine(kRequestsY);
  screen_.text(screen_.number(x, kRequestsY, c.sensorRequests), kRequestsY, " R");
}

void StatusScreen::drawRoom(int x) {
  screen_.clearLine(kRoomY);
  screen_.text(screen_.number(x + 8, kRoomY, modes_.roomId()), kRoomY, "");
  screen_.text(x, kRoomY, "R");
}

void StatusScreen::drawTrip(int x) {
  if (!safety_.tripped()) return;
  static const char* const kWhy[] = {"", "CHECK", "ENCODER", "AVR", "SILENT"};
  screen_.clearLine(kTripY);
  screen_.text(x, kTripY, kWhy[static_cast<int>(safety_.reason())]);
}

void StatusScreen::drawMapPages() {
  if (mapPage_ < 0) return;
  const Pose p = modes_.pose();
  screen_.drawMapPage(modes_.grid(), p.cell, p.heading, blink_, mapPage_);
  if (++mapPage_ == Screen::kMapSize / 8) {
    mapPage_ = -1;
    lcd_.refresh();
  }
}

// A check's condition as the brick keeps it fills one line of the screen (checktext::brief).
static_assert(checktext::kShownChars * Font3x5::kAdvance == Screen::kWidth);

void StatusScreen::showCheckFailed(const char* file, int line, const char* what) {
  screen_.clear();
  screen_.text(0, 0, "CHECK FAILED");
  const char* tail = file;
  for (const char* p = file; *p != 0; ++p) {
    if (*p == '/') tail = p + 1;
  }
  screen_.text(0, 8, tail);
  screen_.number(0, 16, static_cast<uint32_t>(line));
  screen_.text(0, 24, what);
  lcd_.refresh();
}

}  // namespace nxtmap::fw
