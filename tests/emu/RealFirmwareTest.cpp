// The real firmware image (firmware/, built by the test build) in the emulated brick: it boots, brings up
// the AVR link, starts exploring when Enter is pressed, pings all four sensors, drives, and never faults.
#include "EmuTestSupport.hpp"
#include "host/emu/EmulatedRun.hpp"

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR
ElfImage loadFirmware(const std::string& name) {
  ElfLoad l = ElfImage::load(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/" + name);
  if (!l.image) throw std::runtime_error(l.error);
  return std::move(*l.image);
}

// A room of 0.20 m cells (the firmware's own cell size): 10 x 8 cells, one pillar.
sim::World room20() {
  return sim::World::fromRows(
      {"##########", "#........#", "#........#", "#...##...#", "#........#", "#........#", "#........#", "##########"},
      0.20);
}

TEST(RealFirmware, BootsLinksAvrExploresAndNeverFaults) {
  const ElfImage image = loadFirmware("nxtmap.elf");
  const sim::World world = room20();
  EmulatedRunOptions o;
  o.brick.startCol = 2;
  o.brick.startRow = 5;
  // A fresh brick (nothing in flash) first measures its turns (a sweep, four whole turns, a second sweep: about
  // 85 s, FirstOutingEndToEnd), then it drives.
  o.maxSeconds = 100.0;
  o.pressEnterAtS = 1.0;
  EmulatedRun run(image, world, o);
  const EmulatedRunReport r = run.run();
  ASSERT_FALSE(r.fault) << r.fault.describe();
  EXPECT_NEAR(r.emulatedSeconds, 100.0, 0.01);
  EXPECT_GT(r.avrGood, 1000u);  // a 9-byte command or a 13-byte status frame every 2 ms
  EXPECT_EQ(r.avrBad, 0u);
  for (int p = 0; p < 4; ++p) EXPECT_GT(run.brick().sensor(p).pings(), 0u) << "port " << p + 1;
  EXPECT_GT(r.sensorUpdates, 0u);
  EXPECT_GT(r.drivenCm, 10.0);
  EXPECT_TRUE(run.brick().lcd().displayOn());
  EXPECT_GT(run.brick().lcd().dataBytes(), 800u);
  EXPECT_TRUE(run.brick().blueCore().portOpen());
  EXPECT_GT(r.idles, 1000u);  // the firmware sleeps between interrupts
  // Budgets (measured numbers are printed by make bench; here only sanity).
  EXPECT_LT(r.ram.total(), 65536u);
  EXPECT_GT(r.ram.stackBytes, 0u);
}
TEST(RealFirmware, RamRunImageStartsAtItsEntry) {
  const ElfImage image = loadFirmware("nxtmap-ram.elf");
  ASSERT_FALSE(image.hasFlashCode());
  const sim::World world = room20();
  EmulatedRunOptions o;
  o.brick.startCol = 2;
  o.brick.startRow = 5;
  o.maxSeconds = 2.0;
  EmulatedRun run(image, world, o);
  const EmulatedRunReport r = run.run();
  ASSERT_FALSE(r.fault) << r.fault.describe();
  EXPECT_GT(r.avrGood, 200u);
  EXPECT_EQ(r.avrBad, 0u);
}
#endif

}  // namespace
}  // namespace nxtmap::emu::test
