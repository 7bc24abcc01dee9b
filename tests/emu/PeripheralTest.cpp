// The board peripheral models driven by probe programs: AVR link, ultrasonic sensors, wheels and
// tachometers, Bluetooth module, LCD.
#include "EmuTestSupport.hpp"
#include "../support/TempDir.hpp"

#include <cmath>
#include <fstream>

namespace nxtmap::emu::test {
namespace {

TEST(Avr, HandshakeCommandAndStatusFrames) {
  ProbeRun r("avr", BrickConfig{}, 2.0);
  ASSERT_TRUE(r.ok) << r.fault();
  ASSERT_TRUE(r.port().exitCode.has_value());
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], 1u);     // handshake ACKed
  EXPECT_EQ(v[1], 1u);     // command frame ACKed
  EXPECT_EQ(v[2], 1u);     // status frame read
  EXPECT_EQ(v[3], 0xFFu);  // its checksum holds
  EXPECT_EQ(v[4], 7800u * 1000u / 13848u);
  const AvrModel& avr = r.brick->avr();
  EXPECT_TRUE(avr.handshakeDone());
  EXPECT_EQ(avr.motorPower(0), 40);  // the bad frame after it changed nothing
  EXPECT_EQ(avr.motorPower(2), -25);
  EXPECT_TRUE(avr.brake(1));
  EXPECT_TRUE(avr.sensorPowered(0));
  EXPECT_FALSE(avr.sensorPowered(1));
  EXPECT_TRUE(avr.sensorPowered(2));
  EXPECT_EQ(avr.goodFrames(), 2u);
  EXPECT_EQ(avr.badFrames(), 1u);
}

TEST(Sonar, FourSensorsAnswerFromTheSimulatedSonarOverBitBangedI2c) {
  BrickConfig c;
  c.startCol = 3;
  c.startRow = 3;
  c.heading = sim::Heading::E;
  ProbeRun r("sonar", c, 3.0);
  ASSERT_TRUE(r.ok) << r.fault();
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], static_cast<uint32_t>('L'));
  // The same sonar at the same pose, noise-free: front/right/back/left of a robot facing east.
  sim::World w = smallRoom();
  sim::SimRobot ref(w, 3, 3, sim::Heading::E, sim::NoiseProfile{}, 1);
  for (int p = 0; p < 4; ++p)
    EXPECT_EQ(v[1 + static_cast<size_t>(p)], static_cast<uint32_t>(ref.ping(p))) << "port " << p + 1;
  EXPECT_EQ(v[1], 75u);  // facing east from col 3: wall at col 11 -> 7.5 cells of 10 cm
  for (int p = 0; p < 4; ++p) EXPECT_GE(r.brick->sensor(p).pings(), 1u);
}

TEST(Sonar, UnpoweredSensorDoesNotAnswer) {
  // Same program, but the world is the same and the AVR frame never arrives: no handshake -> no 9 V.
  BrickConfig c;
  ProbeRun r("unmodelled", c, 0.1);  // any program that never powers the sensors
  EXPECT_FALSE(r.brick->avr().sensorPowered(0));
  EXPECT_EQ(r.brick->sensor(0).transactions(), 0u);
}

TEST(Drive, MotorsTurnTheRobotAndTachoEdgesCountDegrees) {
  BrickConfig c;
  c.startCol = 5;
  c.startRow = 6;
  c.heading = sim::Heading::N;
  ProbeRun r("tacho", c, 3.0);
  ASSERT_TRUE(r.ok) << r.fault();
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 3u);
  const auto a = static_cast<int32_t>(v[0]), b = static_cast<int32_t>(v[1]), cc = static_cast<int32_t>(v[2]);
  // 50 % = 400 deg/s for 0.5 s (plus the frame latency): about 200 counts, A forward, B backward.
  EXPECT_NEAR(a, 200, 4);
  EXPECT_NEAR(b, -200, 4);
  EXPECT_EQ(cc, 0);
  EXPECT_NEAR(a, r.brick->drive().wheelDeg(0), 1.0);
  EXPECT_NEAR(b, r.brick->drive().wheelDeg(1), 1.0);
  // Left forward, right back: a clockwise turn on the spot of a/2 * d / track * ... degrees.
  const double arcCm = a * 3.14159265358979 * 5.6 / 360.0;
  const double turnDeg = 2.0 * arcCm / 11.2 * 180.0 / 3.14159265358979;
  EXPECT_NEAR(r.brick->robot().headingDeg(), turnDeg, 2.0);
  EXPECT_NEAR(r.brick->robot().xCm(), 55.0, 0.01);
  EXPECT_NEAR(r.brick->robot().yCm(), 65.0, 0.01);
}

TEST(Bluetooth, ConnectOpenStreamAndEchoThroughTheBridge) {
  MemoryLink link;
  link.toBrick = {'a', 'b', 'c', 'd'};
  ProbeRun r("bt", BrickConfig{}, 5.0, &link);
  ASSERT_TRUE(r.ok) << r.fault();
  ASSERT_TRUE(r.port().exitCode.has_value()) << "probe stuck";
  const auto& v = r.port().values;
  ASSERT_EQ(v.size(), 5u);
  EXPECT_EQ(v[0], 0x14u);
  EXPECT_EQ(v[1], 0x1Bu);
  EXPECT_EQ(v[2], 0x16u);
  EXPECT_EQ(v[3], 0x13u);
  EXPECT_EQ(v[4], 1u);
  EXPECT_EQ(std::string(link.fromBrick.begin(), link.fromBrick.end()), "bcde!");
  EXPECT_EQ(r.brick->blueCore().badFrames(), 0u);
  EXPECT_TRUE(r.brick->blueCore().unknownCommands().empty());
}

TEST(Lcd, SpiBytesBecomePixelsAndAPng) {
  ProbeRun r("lcd", BrickConfig{}, 1.0);
  ASSERT_TRUE(r.ok) << r.fault();
  const Lcd& lcd = r.brick->lcd();
  EXPECT_TRUE(lcd.displayOn());
  for (int x = 0; x < 12; ++x)
    for (int y = 0; y < 10; ++y) EXPECT_EQ(lcd.pixel(x, y), x < 10 && y < 8) << x << "," << y;
  EXPECT_TRUE(lcd.pixel(50, 20));
  EXPECT_FALSE(lcd.pixel(50, 19));
  EXPECT_FALSE(lcd.pixel(51, 20));
  nxtmap::test::TempDir dir;
  std::string err;
  ASSERT_TRUE(lcd.savePng(dir.path("lcd.png"), 3, err)) << err;
  std::ifstream png(dir.path("lcd.png"), std::ios::binary);
  char sig[8]{};
  png.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
}

}  // namespace
}  // namespace nxtmap::emu::test

namespace nxtmap::emu::test {
namespace {

// The tacho probe spins the robot: a spin carries the host's random turn error (turnSigmaDeg) and no slip.
TEST(Drive, ASpinsTurnErrorFollowsTheNoiseProfileAndTheSeed) {
  auto runWith = [](double slip, double turnDeg, uint64_t seed) {
    BrickConfig c;
    c.startCol = 5;
    c.startRow = 6;
    c.noise.wheels.slipSigma = slip;
    c.noise.wheels.turnSigmaDeg = turnDeg;
    c.seed = seed;
    ProbeRun r("tacho", c, 3.0);
    EXPECT_TRUE(r.ok) << r.fault();
    return std::make_pair(r.brick->robot().headingDeg(), r.port().values.at(0));
  };
  const auto clean = runWith(0.0, 0.0, 1), a = runWith(0.0, 2.0, 1), b = runWith(0.0, 2.0, 1), c = runWith(0.0, 2.0, 2);
  EXPECT_EQ(a.second, clean.second);  // the encoders count the same wheel turns
  EXPECT_NE(a.first, clean.first);    // but the robot turned otherwise
  EXPECT_EQ(a.first, b.first);        // same seed, same run
  EXPECT_NE(a.first, c.first);
  EXPECT_EQ(runWith(0.05, 0.0, 1).first, clean.first);  // slip is a straight move's error
}

}  // namespace
}  // namespace nxtmap::emu::test
