#include <gtest/gtest.h>

#include <vector>

#include "firmware/drivers/Lcd.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

// The SPI + PDC + A0 pin as the display controller sees them: every byte with the A0 level it was
// sent with (TDR writes and PDC transfers, which complete at once).
struct LcdWire {
  FakeBus bus;
  bool a0 = false;
  std::vector<uint8_t> commands;
  std::vector<std::vector<uint8_t>> dataRuns;
  LcdWire() {
    bus.onRead = [](uint32_t a, uint32_t& v) {
      if (a == kSpiSr) {
        v = kSpiSrTdre | kSpiSrTxempty;
        return true;
      }
      return false;
    };
    bus.onWrite = [this](uint32_t a, uint32_t v) {
      if (a == kPioSodr && (v & kPinLcdA0)) a0 = true;
      if (a == kPioCodr && (v & kPinLcdA0)) a0 = false;
      if (a == kSpiTdr) {
        EXPECT_FALSE(a0) << "command byte sent in data mode";
        commands.push_back(static_cast<uint8_t>(v));
      }
      if (a == kSpiPtcr && (v & (1u << 8))) {
        EXPECT_TRUE(a0) << "frame data sent in command mode";
        const uint8_t* p = bus.pointer(bus.regs[kSpiTpr]);
        dataRuns.emplace_back(p, p + bus.regs[kSpiTcr]);
        bus.regs[kSpiTcr] = 0;
      }
    };
  }
};

// The controller's settings go out in full before every refresh (LEGO's way: a controller upset by a
// glitch recovers within one refresh), the first refresh right after the reset wait.
TEST(Lcd, BringUpWaitsThenResetsThenSendsTheSettingsWithTheFirstRefresh) {
  LcdWire w;
  uint8_t frame[8][100] = {};
  Lcd<FakeBus> lcd(w.bus, frame);
  lcd.init(kMck, 0);
  EXPECT_EQ(w.bus.regs[kSpiMr], 0x000B0011u);
  EXPECT_EQ(w.bus.regs[kSpiCsr2], (24u << 8) | 1u);  // 2 MHz, CPOL
  lcd.pump(19);
  EXPECT_TRUE(w.commands.empty());
  lcd.pump(20);
  EXPECT_EQ(w.commands, (std::vector<uint8_t>{0xE2}));
  lcd.pump(39);
  EXPECT_EQ(w.commands.size(), 1u);
  lcd.pump(40);
  EXPECT_TRUE(lcd.ready());
  EXPECT_EQ(w.commands.size(), 1u);
  lcd.pump(41);
  const std::vector<uint8_t> settings{0xEB, 0x2F, 0xA4, 0xA6, 0x40, 0x81, 0x5A,
                                      0xC4, 0x27, 0x29, 0xA0, 0x88, 0x23, 0xAF};
  std::vector<uint8_t> expected{0xE2};
  expected.insert(expected.end(), settings.begin(), settings.end());
  expected.insert(expected.end(), {0x00, 0x10, 0xB0});
  EXPECT_EQ(w.commands, expected);
}

TEST(Lcd, RefreshSendsEachPageAfterItsAddressOnePagePerPump) {
  LcdWire w;
  uint8_t frame[8][100] = {};
  for (int p = 0; p < 8; ++p)
    for (int x = 0; x < 100; ++x) frame[p][x] = static_cast<uint8_t>(p * 16 + x % 16);
  Lcd<FakeBus> lcd(w.bus, frame);
  lcd.init(kMck, 0);
  lcd.pump(20);
  lcd.pump(40);
  w.commands.clear();
  for (int i = 0; i < 8; ++i) lcd.pump(41 + static_cast<uint32_t>(i));
  ASSERT_EQ(w.dataRuns.size(), 8u);
  const size_t settings = sizeof(Lcd<FakeBus>::kSettings);
  ASSERT_EQ(w.commands.size(), settings + 24u);
  EXPECT_EQ(w.commands.front(), 0xEB);
  EXPECT_EQ(w.commands[settings - 1], 0xAF);  // display on, last
  for (int p = 0; p < 8; ++p) {
    EXPECT_EQ(w.commands[settings + 3 * p], 0x00);
    EXPECT_EQ(w.commands[settings + 3 * p + 1], 0x10);
    EXPECT_EQ(w.commands[settings + 3 * p + 2], 0xB0 | p);
    ASSERT_EQ(w.dataRuns[p].size(), 100u);
    EXPECT_EQ(w.dataRuns[p][17], frame[p][17]);
  }
  lcd.pump(60);  // nothing new to show
  EXPECT_EQ(w.dataRuns.size(), 8u);
  lcd.refresh();
  w.commands.clear();
  lcd.pump(61);
  EXPECT_EQ(w.dataRuns.size(), 9u);
  EXPECT_EQ(w.commands.size(), settings + 3u);  // the settings again, then page 0
  EXPECT_EQ(w.commands[settings - 1], 0xAF);
}

}  // namespace
}  // namespace nxtmap::fw::test
