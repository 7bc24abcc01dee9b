// The machine core with the probe programs: start-up, remap, PIT interrupts, idle fast-forward, RAM use.
#include "EmuTestSupport.hpp"

namespace nxtmap::emu::test {
namespace {

TEST(Machine, BootsRemapsTakesTimerInterruptsAndIdles) {
  ProbeRun r("boot", BrickConfig{}, 5.0);
  ASSERT_TRUE(r.ok) << r.fault();
  ASSERT_TRUE(r.port().exitCode.has_value()) << "main did not return";
  EXPECT_EQ(*r.port().exitCode, 7);
  EXPECT_EQ(r.port().text, "boot ok\n");
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], 0xC0FFEEu);    // static constructor ran
  EXPECT_EQ(v[1], 0x12345678u);  // .data copied from flash
  EXPECT_EQ(v[2], 0u);           // before the remap address 0 showed flash
  EXPECT_EQ(v[3], 0xA11CE5u);    // after it, RAM
  EXPECT_GE(v[4], 100u);
  EXPECT_LE(v[4], 101u);
  const MachineStats s = r.brick->machine().stats();
  // 100 ticks of (3002+1)*16 cycles: about 100 ms of brick time.
  EXPECT_NEAR(secondsFromCycles(s.cycles), 0.100, 0.002);
  EXPECT_GE(s.irqs, 100u);
  EXPECT_GE(s.idles, 100u);
  // The idle time was skipped, not executed.
  EXPECT_LT(s.executed * 20, s.cycles);
  const RamUse ram = r.brick->machine().ramUse();
  EXPECT_GT(ram.stackBytes, 0u);
  EXPECT_LT(ram.stackBytes, 1024u);
  EXPECT_GE(ram.staticBytes, 64u + 8u);
}

TEST(Machine, SameProbeSameCycleCount) {
  ProbeRun a("boot", BrickConfig{}, 5.0);
  ProbeRun b("boot", BrickConfig{}, 5.0);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.brick->machine().stats().executed, b.brick->machine().stats().executed);
  EXPECT_EQ(a.brick->machine().stats().cycles, b.brick->machine().stats().cycles);
}

TEST(Machine, TimesAFunctionFromEntryToReturn) {
  BrickConfig c;
  c.machine.timedFunction = "pit_isr";
  ProbeRun r("boot", c, 5.0);
  ASSERT_TRUE(r.ok) << r.fault();
  const MachineStats s = r.brick->machine().stats();
  EXPECT_GE(s.timedCalls, 100u);
  EXPECT_GT(s.maxTimed, 3u);
  EXPECT_LT(s.maxTimed, 200u);
}

// The costliest timed call, by function: its instructions all attributed (to the timed function and
// whatever it ran), the most first.
TEST(Machine, ProfilesTheCostliestTimedCallByFunction) {
  BrickConfig c;
  c.machine.timedFunction = "pit_isr";
  c.machine.profileTimed = true;
  ProbeRun r("boot", c, 5.0);
  ASSERT_TRUE(r.ok) << r.fault();
  const TimedProfile* p = r.brick->machine().timedProfile();
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->worstTotal(), r.brick->machine().stats().maxTimed);
  const std::vector<FunctionCost> costs = p->byFunction(r.image);
  ASSERT_FALSE(costs.empty());
  uint64_t sum = 0;
  for (size_t i = 0; i < costs.size(); ++i) {
    sum += costs[i].instructions;
    if (i > 0) {
      EXPECT_GE(costs[i - 1].instructions, costs[i].instructions);
    }
  }
  EXPECT_EQ(sum, p->worstTotal());
  EXPECT_EQ(costs[0].name, "pit_isr");
}

TEST(Machine, KeepsNoProfileUnlessAsked) {
  BrickConfig c;
  c.machine.timedFunction = "pit_isr";
  ProbeRun r("boot", c, 1.0);
  ASSERT_TRUE(r.ok) << r.fault();
  EXPECT_EQ(r.brick->machine().timedProfile(), nullptr);
}

// A store that makes an interrupt pending with IRQs enabled: the handler runs one instruction later (before
// the marker's next store), as on the ARM7; not at the end of Unicorn's block.
TEST(Machine, TakesAnInterruptAtTheInstructionAfterTheStoreThatRaisedIt) {
  ProbeRun r("irqlatency", BrickConfig{}, 1.0);
  ASSERT_TRUE(r.ok) << r.fault();
  EXPECT_EQ(r.port().text, "irq ok\n");
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0], 2u) << "AIC_ISCR: 1 = at once, 3 = at the block's end; 2 = one instruction later";
  EXPECT_EQ(v[1], 5u) << "TWI_IER: 4 = at once, 6 = at the block's end; 5 = one instruction later";
  EXPECT_EQ(r.brick->machine().stats().lateIrqs, 0u);
}

TEST(ElfImage, RejectsWhatIsNotAnArmElf) {
  const ElfLoad l = ElfImage::load(std::string(NXTMAP_SOURCE_DIR) + "/README.md");
  EXPECT_FALSE(l.image);
  EXPECT_NE(l.error.find("not an ELF"), std::string::npos) << l.error;
  const ElfLoad m = ElfImage::load("/nonexistent/fw.elf");
  EXPECT_FALSE(m.image);
  EXPECT_NE(m.error.find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace nxtmap::emu::test
