// The board bring-up types write the AT91SAM7S256 register values the datasheet gives (expected
// values below are the datasheet's bit positions written out, not the names under test).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "firmware/board/PioInputs.hpp"
#include "firmware/board/Pmc.hpp"
#include "firmware/board/SystemTimer.hpp"
#include "firmware/board/TimerCounter.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using Writes = std::vector<std::pair<uint32_t, uint32_t>>;

TEST(SystemTimer, PeriodAtMasterClockCountsMck16) {
  struct Case {
    uint32_t mck, hz, piv;
  };
  // PIV + 1 = MCK / 16 / hz (datasheet 14.4: the PIT counts MCK/16).
  const Case cases[] = {{reg::kMck, 1000, 3002}, {48000000, 1000, 2999}, {48000000, 100, 29999}, {16000000, 1, 999999}};
  for (const Case& c : cases) EXPECT_EQ(SystemTimer<FakeBus>::periodValue(c.mck, c.hz), c.piv) << c.hz;
}

TEST(SystemTimer, StartEnablesTheTimerAndItsInterrupt) {
  FakeBus bus;
  SystemTimer<FakeBus> timer(bus);
  timer.start(reg::kMck, 1000);
  EXPECT_EQ(bus.writes, (Writes{{0xFFFFFD30u, 3002u | 0x01000000u | 0x02000000u}}));  // PIT_MR: PIV, PITEN, PITIEN
}

TEST(SystemTimer, DueAndElapsedReadTheStatusAndPicnt) {
  struct Case {
    uint32_t sr, pivr;
    bool due;
    uint32_t elapsed;
  };
  const Case cases[] = {
      {0, 0, false, 0}, {1, 1u << 20, true, 1}, {1, (3u << 20) | 1234u, true, 3}, {0xFFFFFFFEu, 0, false, 0}};
  for (const Case& c : cases) {
    FakeBus bus;
    bus.regs[0xFFFFFD34u] = c.sr;    // PIT_SR
    bus.regs[0xFFFFFD38u] = c.pivr;  // PIT_PIVR: PICNT in 31..20, CPIV below
    SystemTimer<FakeBus> timer(bus);
    EXPECT_EQ(timer.due(), c.due) << c.sr;
    EXPECT_EQ(timer.takeElapsed(), c.elapsed) << c.pivr;
  }
}

TEST(SystemTimer, WatchdogRestartWritesTheKeyAndWdrstt) {
  FakeBus bus;
  SystemTimer<FakeBus> timer(bus);
  timer.restartWatchdog();
  EXPECT_EQ(bus.writes, (Writes{{0xFFFFFD40u, 0xA5000001u}}));  // WDT_CR
}

TEST(PioInputs, FilteredInputsThenChangeInterrupts) {
  FakeBus bus;
  PioInputs<FakeBus> pio(bus);
  const uint32_t pins = (1u << 15) | (1u << 1), pulses = 1u << 15;
  pio.disableInterrupts();
  pio.filteredInputs(pins);
  pio.interruptOnChange(pulses);
  const Writes expected = {{0xFFFFF444u, ~0u},  {0xFFFFF420u, pins}, {0xFFFFF460u, pins},
                           {0xFFFFF400u, pins}, {0xFFFFF414u, pins}, {0xFFFFF440u, pulses}};
  EXPECT_EQ(bus.writes, expected);  // IDR, IFER, PPUDR, PER, ODR, IER
}

TEST(PioInputs, ChangesAndLevelsComeFromIsrAndPdsr) {
  FakeBus bus;
  bus.regs[0xFFFFF44Cu] = 0x8002u;  // PIO_ISR
  bus.regs[0xFFFFF43Cu] = 0x0401u;  // PIO_PDSR
  PioInputs<FakeBus> pio(bus);
  EXPECT_EQ(pio.takeChanges(), 0x8002u);
  EXPECT_EQ(pio.levels(), 0x0401u);
  EXPECT_TRUE(bus.writes.empty());
}

TEST(TimerCounter, InitStopsAndSetsMck2ResetOnRcAndTheCompareInterrupt) {
  FakeBus bus;
  TimerCounter<FakeBus> tc(bus);
  tc.init(834);
  const Writes expected = {{0xFFFA0000u, 0x2u}, {0xFFFA0004u, 0x4000u}, {0xFFFA001Cu, 834u}, {0xFFFA0024u, 0x10u}};
  EXPECT_EQ(bus.writes, expected);  // CCR CLKDIS, CMR TIMER_CLOCK1 | CPCTRG, RC, IER CPCS
  bus.writes.clear();
  tc.start();
  tc.stop();
  EXPECT_EQ(bus.writes, (Writes{{0xFFFA0000u, 0x5u}, {0xFFFA0000u, 0x2u}}));  // CLKEN | SWTRG, CLKDIS
}

TEST(TimerCounter, RcForARateAtMck2) {
  struct Case {
    uint32_t mck, hz, rc;
  };
  const Case cases[] = {{reg::kMck, 28800, 834}, {48000000, 1000, 24000}, {48000000, 24000000, 1}};
  for (const Case& c : cases) EXPECT_EQ(TimerCounter<FakeBus>::rcFor(c.mck, c.hz), c.rc) << c.hz;
}

TEST(Pmc, PeripheralClocksAndIdle) {
  struct Case {
    uint32_t id, bit;
  };
  const Case cases[] = {{reg::kIdPioa, 0x4u}, {reg::kIdTc0, 0x1000u}, {reg::kIdTwi, 0x200u}, {reg::kIdUsart1, 0x80u}};
  for (const Case& c : cases) {
    FakeBus bus;
    Pmc<FakeBus> pmc(bus);
    pmc.enable(c.id);
    EXPECT_EQ(bus.writes, (Writes{{0xFFFFFC10u, c.bit}})) << c.id;  // PMC_PCER
  }
  FakeBus bus;
  Pmc<FakeBus> pmc(bus);
  pmc.idle();
  EXPECT_EQ(bus.writes, (Writes{{0xFFFFFC04u, 1u}}));  // PMC_SCDR: PCK
}

}  // namespace
}  // namespace nxtmap::fw::test
