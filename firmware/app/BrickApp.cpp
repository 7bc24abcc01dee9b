#include "firmware/app/BrickApp.hpp"

#include "common/check/Check.hpp"
#include "firmware/app/Isr.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::fw {
namespace {
constexpr TachoDecoder::Pins kTachoPins[TachoDecoder::kMotors] = {
    {reg::kPinTachoA, reg::kPinDirA}, {reg::kPinTachoB, reg::kPinDirB}, {reg::kPinTachoC, reg::kPinDirC}};
constexpr uint32_t kTickHz = 1000;          // the main loop's millisecond
constexpr uint32_t kSoftI2cTickHz = 28800;  // 3 ticks per bit at 9600 bit/s
constexpr uint16_t kAvrSilentTripMs = 100;
#ifndef NXTMAP_RAM_RUN
// Doorways the brick's rooms are cut at, in cells: 4 .. 15 wide (0.4 .. 1.5 m at 10 cm cells), at
// most 3 deep, each jamb a wall of 2+ cells; the same limits as the PC's house planner
// (host/house/HousePlanner.hpp HouseConfig::doorways) and the stand-in brick (host/link/SimBrick.cpp).
constexpr DoorwayLimits kDoorways{4, 15, 3, 2};
#endif

// Interrupt sources, their AIC priority (0..7, 7 first), handler and trigger. The AVR's TWI moves one
// byte per interrupt and loses the frame if late; it is edge-triggered as in LEGO's d_ioctrl.r (one
// interrupt per rising TXRDY/RXRDY/NACK: TXRDY stays high after a write's last byte). The tick and the
// tacho edges come next, then the soft I2C clock; the BlueCore's USART has its PDC and waits long; the
// speaker's PDC has a buffer queued ahead and waits longest.
using Trigger = Aic<Mmio>::Trigger;
struct IrqRoute {  // 8 bytes: the RAM-run image holds this table too
  IrqHandler handler;
  uint8_t id, priority;
  Trigger trigger;
};
constexpr IrqRoute kIrqRoutes[] = {
    {nxtmapIsrTwi, reg::kIdTwi, 7, Trigger::Edge},
    {nxtmapIsrSystem, reg::kIdSys, 6, Trigger::Level},
    {nxtmapIsrPio, reg::kIdPioa, 6, Trigger::Level},
    {nxtmapIsrTc0, reg::kIdTc0, 5, Trigger::Level},
    {nxtmapIsrUsart1, reg::kIdUsart1, 4, Trigger::Level},
    {nxtmapIsrSsc, static_cast<uint8_t>(ssc::kId), 3, Trigger::Level},
};

// The link as the brick runs it, telling the PC how its sensors read (HelloReply).
protocol::BrickLinkConfig linkConfigFor(const RangeGeometry& geometry) {
  protocol::BrickLinkConfig c;
  c.geometry = protocol::rangeGeometryMsgOf(geometry);
  return c;
}

#ifndef NXTMAP_RAM_RUN
// The house's runs: the first room's sweeps square to the walls (RoomSession), as a run on an empty map does.
PilotConfig housePilot(const BrickConfig& config) {
  PilotConfig p;
  p.squareSweepMrad = config.squareSweepMrad;
  return p;
}
#endif
}  // namespace

NXTMAP_RUN_ONCE BrickApp::BrickApp()
    : tacho_(kTachoPins),
      ports_{{bus_, kSensorPortPins[0]},
             {bus_, kSensorPortPins[1]},
             {bus_, kSensorPortPins[2]},
             {bus_, kSensorPortPins[3]}},
      stack_(storage_.memory(), config_.explorer()),
#ifndef NXTMAP_RAM_RUN
      confinement_(reach_, AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight(), kDoorways,
                   stack_.config().geometry.hitCells()),
      house_(stack_, confinement_, housePilot(config_)),
#endif
      link_(stack_.map().grid(), shadow_, linkConfigFor(stack_.config().geometry)),
      runner_(motion_, sonar_, config_.drive, stack_.config().geometry, config_.sensorPorts),
      modes_(stack_, houseBrick(), runner_, link_, safety_, tacho_, avr_.command(), config_, wheelStore()),
      lego_(modes_, runner_, speaker_, bt_, reg::kMck),
      radio_(bt_, link_, modes_, avr_),
      status_(frame_, lcd_, modes_, bt_, link_, avr_, safety_) {
  link_.attach(lego_);
}

NXTMAP_RUN_ONCE void BrickApp::init() {
  aic_.init(bus_.address(reinterpret_cast<const void*>(nxtmapIsrSpurious)));
  timer_.start(reg::kMck, kTickHz);
  initTachos();
  initSensorPorts();
  initAvr();
  bt_.init(reg::kMck, 0);
  lcd_.init(reg::kMck, 0);
  speaker_.init();
  status_.clear();
  installInterrupts();
}

// Tacho pins: inputs, glitch filter, no pull-ups, change interrupts on the pulse pins.
void BrickApp::initTachos() {
  pmc_.enable(reg::kIdPioa);
  pio_.disableInterrupts();
  pio_.filteredInputs(tacho_.allPins());
  pio_.interruptOnChange(tacho_.pulseMask());
}

// Sensor ports and the soft I2C clock (TC0, started per transaction).
void BrickApp::initSensorPorts() {
  for (auto& p : ports_) p.init();
  pmc_.enable(reg::kIdTc0);
  sonarClock_.init(TimerCounter<Mmio>::rcFor(reg::kMck, kSoftI2cTickHz));
}

// AVR: 9 V constant on all four ports for the ultrasonic sensors, motors braked.
void BrickApp::initAvr() {
  avr_.init();
  avr_.command().inputPower = static_cast<uint8_t>(constant9v(0) | constant9v(1) | constant9v(2) | constant9v(3));
  avr_.command().brakeMask = ModeMachine::kAllBrakes;
  sonar_.powered(0);
}

void BrickApp::installInterrupts() {
  for (const IrqRoute& r : kIrqRoutes)
    aic_.install(r.id, r.priority, bus_.address(reinterpret_cast<const void*>(r.handler)), r.trigger);
}

void BrickApp::onSystem() {
  if (!timer_.due()) return;
  const uint32_t now = ms_ + timer_.takeElapsed();
  ms_ = now;
  tacho_.tick();
  safety_.enforce(avr_.command(), now);
  avr_.tick();
  timer_.restartWatchdog();
}

void BrickApp::onPio() {
  const uint32_t changed = pio_.takeChanges();
  tacho_.onPinChange(pio_.levels(), changed);
}

void BrickApp::onTwi() { avr_.onInterrupt(); }

void BrickApp::onUsart1() { bt_.onInterrupt(); }

void BrickApp::onSsc() { speaker_.onInterrupt(); }

void BrickApp::onTc0() {
  sonarClock_.acknowledge();
  i2c_.tick(ports_[i2cPort_]);
  if (!i2c_.busy()) {
    sonarClock_.stop();
    sonarClockOn_ = false;
  }
}

void BrickApp::startSonarClock() {
  if (!i2c_.busy() || sonarClockOn_) return;
  i2cPort_ = sonar_.port();
  sonarClockOn_ = true;
  sonarClock_.start();
}

// Trips the motor safety on a tacho fault or a silent AVR while the robot moves; a trip stops
// the robot (mode Fault).
void BrickApp::guardMotors(uint32_t nowMs) {
  safety_.feed(nowMs);
  if (tacho_.fault()) safety_.trip(MotorSafety::Reason::Encoder);
  const bool moving = modes_.motorsDriven();  // the robot's run or a PC's LEGO motor commands
  if (moving && avr_.silentMs() > kAvrSilentTripMs) safety_.trip(MotorSafety::Reason::AvrLink);
  if (safety_.tripped() && moving) modes_.halt();
}

void BrickApp::loopOnce() {
  const uint32_t now = ms_;
  guardMotors(now);
  radio_.serve(now);
  if (avr_.up()) modes_.readButton(decodeButton(avr_.status().buttonsRaw), now);
  modes_.drive(now);
  const Beep beep = beeper_.update(modes_.mode(), modes_.finishes());
  if (beep.hz != 0) speaker_.play(reg::kMck, beep.hz, beep.ms);
  startSonarClock();
  modes_.driveMotors();
  status_.draw(now);
  status_.drawMapPages();
  lcd_.pump(now);
}

void BrickApp::run() {
  nxtmapIrqEnable();
  uint32_t last = ms_ - 1;
  for (;;) {
    // One pass per millisecond tick, or sooner when radio bytes wait; the byte-by-byte TWI and
    // soft-I2C interrupts in between need no pass.
    const uint32_t now = ms_;
    if (now != last || bt_.rxPending()) {
      last = now;
      loopOnce();
    }
    // Nothing new: stop the processor clock until the next interrupt.
    if (ms_ == last && !bt_.rxPending()) pmc_.idle();
  }
}

void BrickApp::checkFailed(const char* file, int line, const char* what) {
  safety_.trip(MotorSafety::Reason::Check);
  modes_.halt();
  status_.showCheckFailed(file, line, what);
  nxtmapIrqEnable();
  for (;;) {
    lcd_.pump(ms_);
    pmc_.idle();
  }
}

}  // namespace nxtmap::fw
