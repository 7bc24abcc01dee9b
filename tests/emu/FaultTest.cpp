// Deliberately broken probe programs must stop the run with a clear report: what, where (PC), which address.
#include "EmuTestSupport.hpp"

namespace nxtmap::emu::test {
namespace {

uint32_t symbolOf(const ProbeRun& r, const char* name) {
  const auto v = r.image.symbol(name);
  EXPECT_TRUE(v.has_value()) << name;
  return v.value_or(0) & ~1u;
}

TEST(Faults, UnalignedLoadIsCaughtWithPcAndAddress) {
  ProbeRun r("unaligned", BrickConfig{}, 1.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::Unaligned) << f.describe();
  ASSERT_EQ(r.port().values.size(), 1u);
  EXPECT_EQ(f.address, r.port().values[0]);  // &g_bytes[1]
  EXPECT_EQ(f.address & 3u, 1u);
  const uint32_t main = symbolOf(r, "main");
  EXPECT_GE(f.pc, main);
  EXPECT_LT(f.pc, main + 64);
  EXPECT_NE(f.describe().find("unaligned access at pc=0x"), std::string::npos) << f.describe();
}

TEST(Faults, UnmodelledRegisterIsCaughtWithItsAddress) {
  ProbeRun r("unmodelled", BrickConfig{}, 1.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::UnmodelledIo) << f.describe();
  EXPECT_EQ(f.address, 0xFFFFF240u);
  const uint32_t main = symbolOf(r, "main");
  EXPECT_GE(f.pc, main);
  EXPECT_LT(f.pc, main + 64);
}

TEST(Faults, RunawayRecursionIsAStackOverflow) {
  ProbeRun r("recursion", BrickConfig{}, 1.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::StackOverflow) << f.describe();
  const uint32_t limit = symbolOf(r, "__stack_limit__");
  EXPECT_LT(f.address, limit);
  EXPECT_GE(f.address, limit - 256);
  const uint32_t deeper = symbolOf(r, "_Z6deeperm");
  EXPECT_GE(f.pc, deeper);
  EXPECT_LT(f.pc, deeper + 64);
}

TEST(Faults, Armv5InstructionIsRejectedAsOnTheArm7tdmi) {
  ProbeRun r("armv5", BrickConfig{}, 1.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::Exception) << f.describe();
  const uint32_t main = symbolOf(r, "main");
  EXPECT_GE(f.pc, main);
  EXPECT_LT(f.pc, main + 64);
}

TEST(Faults, ForgottenWatchdogResetsTheBrickAfter16Seconds) {
  ProbeRun r("watchdog", BrickConfig{}, 30.0);
  ASSERT_FALSE(r.ok);
  const EmuFault& f = r.brick->machine().fault();
  EXPECT_EQ(f.kind, FaultKind::Reset) << f.describe();
  EXPECT_NE(f.what.find("watchdog"), std::string::npos);
  // The reset value WDV = 0xFFF: 4096 x 128 slow clocks, 16 s at 32.768 kHz, this brick's RC clock here.
  EXPECT_NEAR(r.brick->seconds(), 4096.0 * 128.0 / r.brick->machine().clock().slowClockHz, 0.01);
}

TEST(Faults, AlignmentCheckCanBeSwitchedOff) {
  BrickConfig c;
  c.machine.checkAlignment = false;
  ProbeRun r("unaligned", c, 1.0);
  EXPECT_TRUE(r.ok) << r.fault();
  EXPECT_TRUE(r.port().exitCode.has_value());
}

}  // namespace
}  // namespace nxtmap::emu::test
