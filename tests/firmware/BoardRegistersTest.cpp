#include <gtest/gtest.h>

#include "firmware/board/Aic.hpp"
#include "firmware/drivers/SensorPortPins.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

TEST(SensorPortPins, EachPortUsesItsDigi0AsSclAndDigi1AsSda) {
  EXPECT_EQ(kSensorPortPins[0].scl, pin(23));
  EXPECT_EQ(kSensorPortPins[0].sda, pin(18));
  EXPECT_EQ(kSensorPortPins[1].scl, pin(28));
  EXPECT_EQ(kSensorPortPins[1].sda, pin(19));
  EXPECT_EQ(kSensorPortPins[2].scl, pin(29));
  EXPECT_EQ(kSensorPortPins[2].sda, pin(20));
  EXPECT_EQ(kSensorPortPins[3].scl, pin(30));
  EXPECT_EQ(kSensorPortPins[3].sda, pin(2));
}

TEST(SensorPortPins, LinesAreDrivenForOurBitsAndReleasedForTheSensors) {
  FakeBus bus;
  SensorPortPins<FakeBus> port(bus, kSensorPortPins[1]);
  port.init();
  const uint32_t both = pin(28) | pin(19);
  EXPECT_EQ(bus.regs[kPioPer], both);    // PIO, not a peripheral
  EXPECT_EQ(bus.regs[kPioPpudr], both);  // the port has its own pull-ups
  EXPECT_EQ(bus.regs[kPioOer], both);    // both outputs, idle high
  EXPECT_EQ(bus.regs[kPioSodr], both);
  bus.writes.clear();
  port.scl(false);
  port.sdaDrive(false);
  port.sdaRelease();
  ASSERT_EQ(bus.writes.size(), 4u);
  EXPECT_EQ(bus.writes[0], std::make_pair(kPioCodr, pin(28)));
  EXPECT_EQ(bus.writes[1], std::make_pair(kPioCodr, pin(19)));
  EXPECT_EQ(bus.writes[2], std::make_pair(kPioOer, pin(19)));
  EXPECT_EQ(bus.writes[3], std::make_pair(kPioOdr, pin(19)));  // input: the sensor may pull it low
  bus.regs[kPioPdsr] = pin(19);
  EXPECT_TRUE(port.sda());
  bus.regs[kPioPdsr] = pin(28);
  EXPECT_FALSE(port.sda());
}

TEST(Aic, InstallSetsPriorityVectorAndEnablesTheSource) {
  FakeBus bus;
  Aic<FakeBus> aic(bus);
  aic.init(0x1234);
  EXPECT_EQ(bus.regs[kAicIdcr], ~0u);
  EXPECT_EQ(bus.regs[kAicDcr], 0u);  // no protect mode
  EXPECT_EQ(bus.regs[kAicSpu], 0x1234u);
  aic.install(kIdTwi, 7, 0x100abc);
  EXPECT_EQ(bus.regs[kAicSmr + 4 * kIdTwi], 7u);  // level-sensitive, priority 7
  EXPECT_EQ(bus.regs[kAicSvr + 4 * kIdTwi], 0x100abcu);
  EXPECT_EQ(bus.regs[kAicIecr], 1u << kIdTwi);
  aic.install(kIdTwi, 7, 0x100abc, Aic<FakeBus>::Trigger::Edge);
  EXPECT_EQ(bus.regs[kAicSmr + 4 * kIdTwi], 0x27u);  // internal edge-triggered (SRCTYPE 1), priority 7
}

}  // namespace
}  // namespace nxtmap::fw::test
