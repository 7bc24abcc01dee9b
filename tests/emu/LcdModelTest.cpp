// The strict UC1601 model: a panel that starts blank and shows nothing until the display is enabled
// (again after a reset), all-pixels-on and inverse as commanded, and a byte that is no UC1601 command
// is a fault. Our firmware (its settings before every refresh) and the LCD probe set it up without one.
#include "EmuTestSupport.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/Lcd.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

void commands(Lcd& lcd, const std::vector<uint8_t>& bytes) {
  for (uint8_t b : bytes) lcd.byte(false, b);
}
// Page 0, column 0: one byte with rows 0..3 dark.
void drawCorner(Lcd& lcd) {
  commands(lcd, {0x00, 0x10, 0xB0});
  lcd.byte(true, 0x0F);
}

TEST(LcdModel, StartsBlankAndShowsNothingUntilTheDisplayIsEnabled) {
  Lcd lcd;
  for (int y = 0; y < Lcd::kHeight; ++y) EXPECT_FALSE(lcd.pixel(0, y));
  drawCorner(lcd);
  EXPECT_FALSE(lcd.pixel(0, 0));  // written to RAM, display still off
  commands(lcd, {0xAF});
  EXPECT_TRUE(lcd.pixel(0, 0));
  EXPECT_FALSE(lcd.pixel(0, 4));
  commands(lcd, {0xE2});  // reset: off again until enabled
  EXPECT_FALSE(lcd.pixel(0, 0));
  commands(lcd, {0xAF});
  EXPECT_TRUE(lcd.pixel(0, 0));
  EXPECT_TRUE(lcd.fault().empty());
}

struct ShowRow {
  std::vector<uint8_t> cmds;
  bool row0, row4;  // pixel (0,0) (written dark) and (0,4) (written clear)
};

TEST(LcdModel, AllPixelsOnAndInverseChangeWhatItShows) {
  const ShowRow rows[] = {
      {{0xAF}, true, false},
      {{0xAF, 0xA7}, false, true},
      {{0xAF, 0xA5}, true, true},
      {{0xAF, 0xA5, 0xA4}, true, false},
      {{0xAF, 0xA7, 0xA6}, true, false},
      {{0xAF, 0xAE}, false, false},
  };
  for (const ShowRow& r : rows) {
    Lcd lcd;
    drawCorner(lcd);
    commands(lcd, r.cmds);
    EXPECT_EQ(lcd.pixel(0, 0), r.row0) << testing::PrintToString(r.cmds);
    EXPECT_EQ(lcd.pixel(0, 4), r.row4) << testing::PrintToString(r.cmds);
  }
}

struct CommandRow {
  std::vector<uint8_t> bytes;
  const char* fault;  // "" = all known
};

TEST(LcdModel, AByteThatIsNoUc1601CommandIsAFault) {
  const CommandRow rows[] = {
      {{0xEB, 0x2F, 0xA4, 0xA6, 0x40, 0x81, 0x5A, 0xC4, 0x27, 0x29, 0xA0, 0x88, 0x23, 0xAF}, ""},  // LEGO's settings
      {{0xE2, 0xE3, 0x89, 0x24, 0x7F, 0xB8, 0xC0, 0xE8}, ""},
      {{0x81, 0xE4}, ""},  // 0xE4 is the potentiometer's argument, not a command
      {{0x32}, "unknown UC1601 command 0x32"},
      {{0xE4}, "unknown UC1601 command 0xE4"},
      {{0x82}, "unknown UC1601 command 0x82"},
      {{0xB9}, "unknown UC1601 command 0xB9"},
      {{0xAF, 0xD0, 0xFF}, "unknown UC1601 command 0xD0"},  // the first one is named
  };
  for (const CommandRow& r : rows) {
    Lcd lcd;
    commands(lcd, r.bytes);
    EXPECT_EQ(lcd.fault(), r.fault) << testing::PrintToString(r.bytes);
  }
}

TEST(LcdModel, TheLcdProbeSetsItUpWithoutAFault) {
  ProbeRun r("lcd", BrickConfig{}, 1.0);
  ASSERT_TRUE(r.ok) << r.fault();
  EXPECT_TRUE(r.brick->lcd().fault().empty()) << r.brick->lcd().fault();
  EXPECT_TRUE(r.brick->lcd().displayOn());
}

// A byte the UC1601 does not know stops the run with a fault that names it (the probe has more to do after it).
TEST(LcdModel, AnUnknownCommandStopsTheMachine) {
  ProbeRun r("lcdfault", BrickConfig{}, 1.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::Model);
  EXPECT_EQ(f.what, "LCD: unknown UC1601 command 0x3A");
  EXPECT_EQ(r.brick->lcd().fault(), "unknown UC1601 command 0x3A");
  EXPECT_FALSE(r.port().exitCode.has_value());  // main never returned
  EXPECT_LT(r.brick->seconds(), 0.5);
}

#ifdef NXTMAP_EMU_FIRMWARE_DIR
// Our firmware sends its settings before every refresh: many times over 3 s, never an unknown byte.
TEST(LcdModel, OurFirmwareResendsItsSettingsAndNeverFaultsTheController) {
  ElfLoad l = ElfImage::load(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf");
  ASSERT_TRUE(l.image) << l.error;
  const sim::World world = smallRoom();
  EmulatedRunOptions o;
  o.maxSeconds = 3.0;
  EmulatedRun run(*l.image, world, o);
  const EmulatedRunReport rep = run.run();
  ASSERT_FALSE(rep.fault) << rep.fault.describe();
  const Lcd& lcd = run.brick().lcd();
  EXPECT_TRUE(lcd.fault().empty()) << lcd.fault();
  EXPECT_TRUE(lcd.displayOn());
  EXPECT_GT(lcd.commandBytes(), 10u * 14u);  // at least ten refreshes, each with the 14 settings
}
#endif

}  // namespace
}  // namespace nxtmap::emu::test
