// The ADC at register level (AT91SAM7S datasheet, ADC chapter) and as a brick on batteries reads its
// channels: CDR4 (USB VBUS) 0 with no cable, CDR6 the BlueCore's CMD signal, CDR1/2/3/7 the DIGI1 wire of
// sensor ports 1-4 (PA18, PA19, PA20, PA2), channels 0 and 5 unwired.
#include "host/emu/Adc.hpp"

#include <gtest/gtest.h>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCr = 0x00, kMr = 0x04, kCher = 0x10, kChdr = 0x14, kChsr = 0x18, kSr = 0x1C, kLcdr = 0x20,
                   kIer = 0x24, kIdr = 0x28, kImr = 0x2C;
constexpr uint32_t cdr(uint32_t ch) { return 0x30 + 4 * ch; }
constexpr uint32_t kStart = 2, kSwrst = 1;

struct Rig {
  bool bc4 = false;
  uint32_t lowPins = 0;  // PIOA pins pulled low
  Adc adc{[this] { return bc4; }, [this](int pin) { return !((lowPins >> pin) & 1u); }};
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    EXPECT_TRUE(adc.read(off, v)) << off;
    return v;
  }
  void set(uint32_t off, uint32_t v) { EXPECT_TRUE(adc.write(off, v)) << off; }
};

TEST(Adc, ChannelsReadAsABrickOnBatteriesWithNothingPluggedIn) {
  struct Row {
    const char* what;
    bool bc4;
    uint32_t lowPins, mr;
    uint32_t expect[8];
  };
  const Row rows[] = {
      {"idle brick", false, 0, 0, {0, 0x3FF, 0x3FF, 0x3FF, 0, 0, 0, 0x3FF}},
      {"BlueCore stream open", true, 0, 0, {0, 0x3FF, 0x3FF, 0x3FF, 0, 0, 0x3FF, 0x3FF}},
      {"port 1 DIGI1 (PA18) pulled low", false, 1u << 18, 0, {0, 0, 0x3FF, 0x3FF, 0, 0, 0, 0x3FF}},
      {"port 4 DIGI1 (PA2) pulled low", false, 1u << 2, 0, {0, 0x3FF, 0x3FF, 0x3FF, 0, 0, 0, 0}},
      {"LOWRES: 8-bit results", true, 0, 1u << 4, {0, 0xFF, 0xFF, 0xFF, 0, 0, 0xFF, 0xFF}},
  };
  for (const Row& r : rows) {
    Rig g;
    g.bc4 = r.bc4;
    g.lowPins = r.lowPins;
    g.set(kMr, r.mr);
    g.set(kCher, 0xFF);
    g.set(kCr, kStart);
    for (uint32_t ch = 0; ch < 8; ++ch) EXPECT_EQ(g.reg(cdr(ch)), r.expect[ch]) << r.what << ", channel " << ch;
  }
}

TEST(Adc, OnlyEnabledChannelsConvertAndSetTheirEndOfConversion) {
  Rig g;
  g.bc4 = true;
  g.set(kCher, (1u << 4) | (1u << 6));
  g.set(kCher, 1u << 1);
  g.set(kChdr, 1u << 1);
  EXPECT_EQ(g.reg(kChsr), (1u << 4) | (1u << 6));
  EXPECT_EQ(g.reg(kSr), 0u);
  g.set(kCr, kStart);
  // channel 6 ends while DRDY from channel 4 is set: a general overrun (LCDR was not read in between)
  EXPECT_EQ(g.reg(kSr), (1u << 4) | (1u << 6) | Adc::kDrdy | Adc::kGovre);
  EXPECT_EQ(g.reg(kLcdr), 0x3FFu);               // the last converted: channel 6
  EXPECT_EQ(g.reg(kSr), (1u << 4) | (1u << 6));  // DRDY cleared by the LCDR read
  EXPECT_EQ(g.reg(cdr(6)), 0x3FFu);
  EXPECT_EQ(g.reg(kSr), 1u << 4);  // EOC6 cleared by the CDR6 read
  EXPECT_EQ(g.reg(cdr(1)), 0u);    // never converted
}

TEST(Adc, AConversionOverAnUnreadResultSetsOverrunUntilSrIsRead) {
  Rig g;
  g.set(kCher, 1u << 6);
  g.set(kCr, kStart);
  g.set(kCr, kStart);  // CDR6 and LCDR never read
  EXPECT_EQ(g.reg(kSr), (1u << 6) | (1u << 14) | Adc::kDrdy | Adc::kGovre);
  EXPECT_EQ(g.reg(kSr), (1u << 6) | Adc::kDrdy);  // OVRE6 and GOVRE cleared by the read
  g.reg(cdr(6));
  g.reg(kLcdr);
  g.set(kCr, kStart);
  EXPECT_EQ(g.reg(kSr), (1u << 6) | Adc::kDrdy);  // read in time: no overrun
}

TEST(Adc, InterruptLineFollowsSrAndImr) {
  Rig g;
  g.set(kCher, 1u << 6);
  g.set(kIer, Adc::kDrdy | (1u << 6));
  g.set(kIdr, 1u << 6);
  EXPECT_EQ(g.reg(kImr), Adc::kDrdy);
  EXPECT_FALSE(g.adc.irqLine());
  g.set(kCr, kStart);
  EXPECT_TRUE(g.adc.irqLine());
  g.reg(kLcdr);
  EXPECT_FALSE(g.adc.irqLine());
}

TEST(Adc, SoftwareResetClearsEveryRegister) {
  Rig g;
  g.set(kMr, 0x0F1F3F3F);
  g.set(kCher, 0xFF);
  g.set(kIer, Adc::kDrdy);
  g.set(kCr, kStart);
  g.set(kCr, kSwrst);
  for (uint32_t off : {kMr, kChsr, kSr, kLcdr, kImr, cdr(1), cdr(7)}) EXPECT_EQ(g.reg(off), 0u) << off;
  EXPECT_FALSE(g.adc.irqLine());
}

TEST(Adc, ModeRegisterKeepsOnlyItsFields) {
  Rig g;
  g.set(kMr, 0xFFFFFFFF);
  EXPECT_EQ(g.reg(kMr), 0x0F1F3F3Fu);  // TRGEN, TRGSEL, LOWRES, SLEEP, PRESCAL, STARTUP, SHTIM
}

}  // namespace
}  // namespace nxtmap::emu::test
