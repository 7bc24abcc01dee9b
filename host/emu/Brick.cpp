#include "host/emu/Brick.hpp"

#include "host/sim/RobotPlacement.hpp"

#include <cmath>

namespace nxtmap::emu {

namespace {
constexpr uint64_t kCrosstalkWindow = kMckHz / 1000 * 30;  // pings within 30 ms hear each other

// The robot set down in the site as the configuration says.
sim::RobotPlacement placementFor(const sim::Site& site, const BrickConfig& c) {
  return sim::placeRobot(site, sim::PlacementRequest{c.robot, c.startPose, c.startCol, c.startRow, c.heading,
                                                     c.startJitterDeg, c.seed, c.mountOffsetCm});
}
sim::SimRobot robotFor(const sim::RobotPlacement& placed, const BrickConfig& c) {
  return sim::SimRobot(placed.scene, placed.robot, placed.grid.frame, placed.start.cm, placed.start.headingDeg, c.noise,
                       c.seed, 255.0);
}
}  // namespace

Brick::Brick(const ElfImage& image, const sim::World& world, const BrickConfig& c)
    : Brick(image, sim::siteFromRaster(world), c) {}

Brick::Brick(const ElfImage& image, const sim::Site& site, const BrickConfig& c)
    : placement_(placementFor(site, c)),
      robot_(robotFor(placement_, c)),
      machine_(image, c.machine),
      pioa_(machine_.clock()),
      twi_(machine_.clock(), avr_),
      drive_(machine_.clock(), avr_, pioa_, robot_, c.drive, c.seed),
      bc4_(machine_.clock(), pioa_, c.link),
      usart_(machine_.clock(), machine_, bc4_),
      spi_(machine_.clock(), machine_, pioa_, lcd_),
      adc_([this] { return bc4_.cmdSignal(); }, [this](int pin) { return pioa_.level(pin); }),
      tc_(machine_.clock()),
      pwm_(machine_.clock()),
      ssc_(machine_.clock(), machine_),
      buttons_(avr_, c.pressEnterAtS < 0 ? kNever : static_cast<uint64_t>(c.pressEnterAtS * kMckHz),
               cyclesFromMs(300)) {
  machine_.clock().slowClockHz = slowClockHzForSeed(c.seed);  // this brick's RC slow clock
  lcd_.onFault([this](const std::string& what) { machine_.reportModelFault("LCD: " + what); });
  machine_.attach(Pioa::kBase, Pioa::kSize, pioa_);
  machine_.attach(Twi::kBase, Twi::kSize, twi_);
  machine_.attach(Usart::kBase1, Usart::kSize, usart_);
  machine_.attach(Spi::kBase, Spi::kSize, spi_);
  machine_.attach(Adc::kBase, Adc::kSize, adc_);
  machine_.attach(TimerCounter::kBase, TimerCounter::kSize, tc_);
  machine_.attach(Pwm::kBase, Pwm::kSize, pwm_);
  machine_.attach(Ssc::kBase, Ssc::kSize, ssc_);
  machine_.attach(Udp::kBase, Udp::kSize, udp_);
  machine_.addTimeSource(drive_);
  machine_.addTimeSource(bc4_);
  machine_.addTimeSource(buttons_);
  Aic& aic = machine_.aic();
  aic.connect(Aic::kIdPioa, [this] { return pioa_.irqLine(); });
  aic.connect(Aic::kIdTwi, [this] { return twi_.irqLine(); });
  aic.connect(Aic::kIdUs1, [this] { return usart_.irqLine(); });
  aic.connect(Aic::kIdSpi, [this] { return spi_.irqLine(); });
  aic.connect(Aic::kIdAdc, [this] { return adc_.irqLine(); });
  aic.connect(Aic::kIdSsc, [this] { return ssc_.irqLine(); });
  aic.connect(Aic::kIdPwm, [this] { return pwm_.irqLine(); });
  for (int ch = 0; ch < 3; ++ch) aic.connect(12 + ch, [this, ch] { return tc_.irqLine(ch); });
  pioa_.observe([this](uint32_t levels) { tc_.pinsChanged(levels); });  // TIOA0..2: the tacho pulse pins
  tc_.pinsChanged(pioa_.levels());
  for (int p = 0; p < 4; ++p)
    sensors_[static_cast<size_t>(p)] = std::make_unique<UltrasonicSensor>(
        machine_.clock(), pioa_, avr_, robot_, p, c.portFacing[static_cast<size_t>(p)],
        [this](int port) { return othersFiring(port); });
  if (c.testPort) {
    testPort_ = std::make_unique<TestPort>();
    machine_.attach(TestPort::kBase, TestPort::kSize, *testPort_);
  }
  if (c.link) {
    LinkEndpoint* link = c.link;
    machine_.setExternalWait([link] { return link->waitForActivity(200); });
  }
}

bool Brick::othersFiring(int port) const {
  const uint64_t now = machine_.stats().cycles;
  for (int p = 0; p < 4; ++p) {
    if (p == port || !avr_.sensorPowered(p)) continue;
    const UltrasonicSensor& s = *sensors_[static_cast<size_t>(p)];
    if (s.mode() == 0x02) return true;
    if (s.pings() > 0 && now - s.lastPingAt() < kCrosstalkWindow) return true;
  }
  return false;
}

bool Brick::runFor(double seconds, const std::function<bool()>& stop) {
  const auto until = static_cast<uint64_t>(std::llround(seconds * static_cast<double>(kMckHz)));
  TestPort* tp = testPort_.get();
  return machine_.run(until, [&] { return (tp && tp->exitCode) || (stop && stop()); });
}

}  // namespace nxtmap::emu
