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

TEST(Lcd, BringUpWaitsThenResetsThenInitialises) {
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
  EXPECT_EQ(w.commands, (std::vector<uint8_t>{0xE2, 0xEB, 0x81, 0x5C, 0x89, 0xC4, 0xAF}));
  EXPECT_TRUE(lcd.ready());
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
  ASSERT_EQ(w.commands.size(), 24u);
  for (int p = 0; p < 8; ++p) {
    EXPECT_EQ(w.commands[3 * p], 0x00);
    EXPECT_EQ(w.commands[3 * p + 1], 0x10);
    EXPECT_EQ(w.commands[3 * p + 2], 0xB0 | p);
    ASSERT_EQ(w.dataRuns[p].size(), 100u);
    EXPECT_EQ(w.dataRuns[p][17], frame[p][17]);
  }
  lcd.pump(60);  // nothing new to show
  EXPECT_EQ(w.dataRuns.size(), 8u);
  lcd.refresh();
  lcd.pump(61);
  EXPECT_EQ(w.dataRuns.size(), 9u);
}

}  // namespace
}  // namespace nxtmap::fw::test
