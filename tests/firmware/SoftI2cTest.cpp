#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "firmware/drivers/SoftI2c.hpp"
#include "tests/firmware/I2cSlaveModel.hpp"

namespace nxtmap::fw::test {
namespace {

std::string joined(const std::vector<std::string>& t) {
  std::string s;
  for (const auto& e : t) s += (s.empty() ? "" : " ") + e;
  return s;
}

// Ticks the engine until it finishes; returns the ticks used.
int run(SoftI2c& i2c, I2cSlaveModel& bus, int limit = 2000) {
  int n = 0;
  while (i2c.busy() && n < limit) {
    i2c.tick(bus);
    ++n;
  }
  return n;
}

TEST(SoftI2c, WriteSendsAddressRegisterAndDataWithAcks) {
  SoftI2c i2c;
  I2cSlaveModel sensor(0x01);
  const uint8_t cmd[2] = {0x41, 0x01};
  ASSERT_TRUE(i2c.start(0x01, cmd, 2, 0));
  const int ticks = run(i2c, sensor);
  EXPECT_EQ(i2c.result(), SoftI2c::Result::Done);
  EXPECT_EQ(joined(sensor.trace), "S W:02 A W:41 A W:01 A P");
  ASSERT_EQ(sensor.registerWrites.size(), 1u);
  EXPECT_EQ(sensor.registerWrites[0], std::make_pair(uint8_t{0x41}, uint8_t{0x01}));
  EXPECT_TRUE(sensor.idle());
  EXPECT_EQ(ticks, 3 + 3 * 27 + 3);  // start, 3 bytes x 9 bits x 3 ticks, stop
}

TEST(SoftI2c, ReadUsesTheLegoStopExtraClockRestart) {
  SoftI2c i2c;
  I2cSlaveModel sensor(0x01);
  sensor.requireLegoRestart = true;
  sensor.regs[0x42] = 87;
  const uint8_t reg = 0x42;
  ASSERT_TRUE(i2c.start(0x01, &reg, 1, 1));
  run(i2c, sensor);
  ASSERT_EQ(i2c.result(), SoftI2c::Result::Done);
  ASSERT_EQ(i2c.readCount(), 1);
  EXPECT_EQ(i2c.readData()[0], 87);
  // STOP, one clock pulse with the bus free, then a new START before the read address.
  EXPECT_EQ(joined(sensor.trace), "S W:02 A W:42 A P C S W:03 A R:57 N P");
  EXPECT_FALSE(sensor.sawContention);
  EXPECT_TRUE(sensor.idle());
}

TEST(SoftI2c, ReadsSeveralBytesAckingAllButTheLast) {
  SoftI2c i2c;
  I2cSlaveModel sensor(0x01);
  const char* id = "LEGO";
  for (int i = 0; i < 4; ++i) sensor.regs[0x08 + i] = static_cast<uint8_t>(id[i]);
  const uint8_t reg = 0x08;
  ASSERT_TRUE(i2c.start(0x01, &reg, 1, 4));
  run(i2c, sensor);
  ASSERT_EQ(i2c.result(), SoftI2c::Result::Done);
  ASSERT_EQ(i2c.readCount(), 4);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(i2c.readData()), 4), "LEGO");
  EXPECT_EQ(joined(sensor.trace), "S W:02 A W:08 A P C S W:03 A R:4c A R:45 A R:47 A R:4f N P");
}

TEST(SoftI2c, MissingSensorGivesNackAndFreesTheBus) {
  SoftI2c i2c;
  I2cSlaveModel nobody(0x01);
  nobody.present = false;
  const uint8_t reg = 0x42;
  ASSERT_TRUE(i2c.start(0x01, &reg, 1, 1));
  run(i2c, nobody);
  EXPECT_EQ(i2c.result(), SoftI2c::Result::Nack);
  EXPECT_EQ(joined(nobody.trace), "S W:02 N P");
  EXPECT_TRUE(nobody.idle());
}

TEST(SoftI2c, WrongAddressIsNacked) {
  SoftI2c i2c;
  I2cSlaveModel other(0x05);
  const uint8_t reg = 0x42;
  ASSERT_TRUE(i2c.start(0x01, &reg, 1, 0));
  run(i2c, other);
  EXPECT_EQ(i2c.result(), SoftI2c::Result::Nack);
}

TEST(SoftI2c, OneTransactionAtATimeAndSizeLimits) {
  SoftI2c i2c;
  I2cSlaveModel sensor(0x01);
  const uint8_t data[SoftI2c::kMaxWrite + 1] = {};
  EXPECT_FALSE(i2c.start(0x01, data, SoftI2c::kMaxWrite + 1, 0));
  EXPECT_FALSE(i2c.start(0x01, data, 1, SoftI2c::kMaxRead + 1));
  ASSERT_TRUE(i2c.start(0x01, data, 1, 0));
  EXPECT_FALSE(i2c.start(0x01, data, 1, 0));
  run(i2c, sensor);
  EXPECT_EQ(i2c.result(), SoftI2c::Result::Done);
  i2c.release();
  EXPECT_EQ(i2c.result(), SoftI2c::Result::Idle);
  EXPECT_TRUE(i2c.start(0x01, data, 1, 0));
}

}  // namespace
}  // namespace nxtmap::fw::test
