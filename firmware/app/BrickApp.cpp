#include "firmware/app/BrickApp.hpp"

#include <new>

#include "common/check/Check.hpp"
#include "firmware/app/Isr.hpp"

namespace nxtmap::fw {
namespace {
constexpr TachoDecoder::Pins kTachoPins[TachoDecoder::kMotors] = {
    {reg::kPinTachoA, reg::kPinDirA}, {reg::kPinTachoB, reg::kPinDirB}, {reg::kPinTachoC, reg::kPinDirC}};
constexpr uint32_t kDrawPeriodMs = 250;
constexpr uint32_t kButtonStableMs = 50;
constexpr uint16_t kAvrSilentTripMs = 100;
constexpr uint32_t kSoftI2cTickRc = reg::kMck / 2 / 28800;  // 3 ticks per bit at 9600 bit/s
}  // namespace

// Counts filtered readings fed to the explorer; the emulator times nxtmapSensorUpdate.
extern "C" {
volatile uint32_t g_sensorUpdates = 0;
__attribute__((noinline)) Action nxtmapSensorUpdate(Explorer* explorer, const Event* e) {
  const Action a = explorer->step(*e);
  g_sensorUpdates = g_sensorUpdates + 1;
  return a;
}
}

BrickApp::BrickApp()
    : tacho_(kTachoPins),
      ports_{{bus_, kSensorPortPins[0]}, {bus_, kSensorPortPins[1]}, {bus_, kSensorPortPins[2]},
             {bus_, kSensorPortPins[3]}},
      map_(storage_.map.view(), BrickExplorerStorage::kWidth(), BrickExplorerStorage::kHeight()),
      planner_(storage_.travel.view(), BrickExplorerStorage::kWidth(), BrickExplorerStorage::kHeight()),
      explorerConfig_(config_.explorer()),
      runner_(motion_, sonar_, config_.drive, explorerConfig_.geometry, config_.sensorPorts) {}

void BrickApp::init() {
  using namespace reg;
  auto addr = [this](void (*f)()) { return bus_.address(reinterpret_cast<const void*>(f)); };
  aic_.init(addr(nxtmapIsrSpurious));
  // 1 ms tick.
  bus_.write(kPitMr, (kMck / 16 / 1000 - 1) | (1u << 24) | (1u << 25));
  // Tacho pins: inputs, glitch filter, no pull-ups, change interrupts on the pulse pins.
  bus_.write(kPmcPcer, 1u << kIdPioa);
  bus_.write(kPioIdr, ~0u);
  bus_.write(kPioIfer, tacho_.allPins());
  bus_.write(kPioPpudr, tacho_.allPins());
  bus_.write(kPioPer, tacho_.allPins());
  bus_.write(kPioOdr, tacho_.allPins());
  (void)bus_.read(kPioIsr);
  bus_.write(kPioIer, tacho_.pulseMask());
  // Sensor ports and the soft I2C clock (TC0, started per transaction).
  for (auto& p : ports_) p.init();
  bus_.write(kPmcPcer, 1u << kIdTc0);
  bus_.write(kTc0Ccr, kTcCcrClkdis);
  bus_.write(kTc0Cmr, 1u << 14);  // MCK/2, reset on RC compare
  bus_.write(kTc0Rc, kSoftI2cTickRc);
  bus_.write(kTc0Ier, 1u << 4);  // CPCS
  // AVR: 9 V constant on all four ports for the ultrasonic sensors, motors braked.
  avr_.init(kMck);
  avr_.command().inputPower = static_cast<uint8_t>(constant9v(0) | constant9v(1) | constant9v(2) | constant9v(3));
  avr_.command().brakeMask = 0x07;
  sonar_.powered(0);
  bt_.init(kMck, 0);
  lcd_.init(kMck, 0);
  screen_.clear();
  aic_.install(kIdTwi, 7, addr(nxtmapIsrTwi));
  aic_.install(kIdSys, 6, addr(nxtmapIsrSystem));
  aic_.install(kIdPioa, 6, addr(nxtmapIsrPio));
  aic_.install(kIdTc0, 5, addr(nxtmapIsrTc0));
  aic_.install(kIdUsart1, 4, addr(nxtmapIsrUsart1));
}

void BrickApp::onSystem() {
  using namespace reg;
  if ((bus_.read(kPitSr) & 1u) == 0) return;
  const uint32_t elapsed = bus_.read(kPitPivr) >> 20;
  const uint32_t now = ms_ + elapsed;
  ms_ = now;
  tacho_.tick();
  safety_.enforce(avr_.command(), now);
  avr_.tick();
  bus_.write(kWdtCr, 0xA5000001u);
}

void BrickApp::onPio() {
  const uint32_t changed = bus_.read(reg::kPioIsr);
  tacho_.onPinChange(bus_.read(reg::kPioPdsr), changed);
}

void BrickApp::onTwi() { avr_.onInterrupt(); }

void BrickApp::onUsart1() { bt_.onInterrupt(); }

void BrickApp::onTc0() {
  (void)bus_.read(reg::kTc0Sr);
  i2c_.tick(ports_[i2cPort_]);
  if (!i2c_.busy()) {
    bus_.write(reg::kTc0Ccr, reg::kTcCcrClkdis);
    sonarClockOn_ = false;
  }
}

void BrickApp::startSonarClock() {
  if (!i2c_.busy() || sonarClockOn_) return;
  i2cPort_ = sonar_.port();
  sonarClockOn_ = true;
  bus_.write(reg::kTc0Ccr, reg::kTcCcrClken | reg::kTcCcrSwtrg);
}

ActionRunner::Wheels BrickApp::wheels() const {
  return ActionRunner::Wheels{tacho_.count(config_.leftMotor), tacho_.count(config_.rightMotor)};
}

void BrickApp::startExploring(Strategy s) {
  if (mode_ == Mode::Exploring) return;
  safety_.clear();
  tacho_.clearFault();
  if (explorer_ == nullptr || explorer_->finished()) {
    map_.clear();
    if (s == Strategy::Frontier) explorer_ = new (explorerBuf_) FrontierExplorer(map_, planner_, explorerConfig_);
    else explorer_ = new (explorerBuf_) PropagationExplorer(map_, planner_, explorerConfig_);
    runner_.begin(explorer_->step(Event::start()), wheels(), ms_);
  } else if (!runner_.busy()) {
    // Resume after a stop: redo the interrupted action from scratch is not possible (the explorer
    // waits for its answer), so a stopped run resumes by re-reading the front sensor.
    runner_.begin(Action::read(Sensor::Front), wheels(), ms_);
  }
  mode_ = Mode::Exploring;
}

void BrickApp::stop() {
  runner_.abort();
  if (mode_ == Mode::Exploring) mode_ = Mode::Idle;
}

void BrickApp::newRoom() {
  stop();
  explorer_ = nullptr;
  map_.clear();
  mode_ = Mode::Idle;
}

Action BrickApp::feed(const Event& e) {
  if (e.kind == Event::Kind::Range) return nxtmapSensorUpdate(explorer_, &e);
  return explorer_->step(e);
}

void BrickApp::driveExplorer(uint32_t now) {
  Event e;
  if (!runner_.poll(wheels(), now, e)) return;
  const Action next = feed(e);
  if (next.kind == Action::Kind::Done || explorer_->finished()) {
    mode_ = Mode::Done;
    return;
  }
  runner_.begin(next, wheels(), now);
}

void BrickApp::driveMotors() {
  AvrCommand& cmd = avr_.command();
  if (safety_.tripped()) return;  // the tick holds them at 0 with the brake on
  const int8_t left = mode_ == Mode::Exploring ? runner_.power(0) : 0;
  const int8_t right = mode_ == Mode::Exploring ? runner_.power(1) : 0;
  cmd.pwm[config_.leftMotor] = left;
  cmd.pwm[config_.rightMotor] = right;
  uint8_t brake = 0x07;
  if (left != 0) brake = static_cast<uint8_t>(brake & ~(1u << config_.leftMotor));
  if (right != 0) brake = static_cast<uint8_t>(brake & ~(1u << config_.rightMotor));
  cmd.brakeMask = brake;
}

void BrickApp::readButtons(uint32_t now) {
  if (!avr_.up()) return;
  const Button b = decodeButton(avr_.status().buttonsRaw);
  if (b != candidate_) {
    candidate_ = b;
    candidateSince_ = now;
    return;
  }
  if (now - candidateSince_ < kButtonStableMs || b == lastButton_) return;
  lastButton_ = b;
  if (b == Button::Enter) startExploring(Strategy::Propagation);
  else if (b == Button::Right) startExploring(Strategy::Frontier);
  else if (b == Button::Exit) stop();
}

void BrickApp::draw(uint32_t now) {
  if (now - lastDrawMs_ < kDrawPeriodMs) return;
  lastDrawMs_ = now;
  blink_ = !blink_;
  const Pose pose = explorer_ != nullptr ? explorer_->pose() : Pose{};
  screen_.drawMap(map_.grid(), pose.cell, pose.heading, blink_);
  const int x = Screen::kTextX;
  static const char* const kModes[] = {"IDLE", "RUN", "DONE", "STOP"};
  screen_.clearLine(0);
  screen_.text(x, 0, kModes[static_cast<int>(mode_)]);
  screen_.clearLine(7);
  const uint32_t mv = batteryMillivolts(avr_.status().batteryRaw);
  int cx = screen_.number(x, 7, mv / 1000);
  cx = screen_.text(cx, 7, ".");
  cx = screen_.number(cx, 7, (mv / 100) % 10);
  screen_.text(cx, 7, "V");
  static const char* const kBt[] = {"BT OFF", "BT RST", "BT RST", "BT PORT", "BT LIST", "BT ACC", "BT OPEN", "BT LINK"};
  screen_.clearLine(14);
  screen_.text(x, 14, kBt[static_cast<int>(bt_.state())]);
  screen_.clearLine(21);
  screen_.text(x, 21, avr_.up() ? "AVR OK" : "AVR --");
  if (explorer_ != nullptr) {
    const Counters& c = explorer_->counters();
    screen_.clearLine(30);
    screen_.text(screen_.number(x, 30, c.cellsMoved), 30, " C");
    screen_.clearLine(37);
    screen_.text(screen_.number(x, 37, c.sensorRequests), 37, " R");
  }
  if (safety_.tripped()) {
    static const char* const kWhy[] = {"", "CHECK", "ENCODER", "AVR", "SILENT"};
    screen_.clearLine(50);
    screen_.text(x, 50, kWhy[static_cast<int>(safety_.reason())]);
  }
  lcd_.refresh();
}

void BrickApp::loopOnce() {
  const uint32_t now = ms_;
  safety_.feed(now);
  if (tacho_.fault()) safety_.trip(MotorSafety::Reason::Encoder);
  if (mode_ == Mode::Exploring && avr_.silentMs() > kAvrSilentTripMs) safety_.trip(MotorSafety::Reason::AvrLink);
  if (safety_.tripped() && mode_ == Mode::Exploring) {
    runner_.abort();
    mode_ = Mode::Fault;
  }

  const uint32_t epoch = bt_.linkEpoch();
  bt_.poll(now);
  if (bt_.linkEpoch() != epoch) radio_.linkLost();
  uint8_t b;
  while (bt_.readByte(b)) radio_.receive(b);

  readButtons(now);
  if (mode_ == Mode::Exploring) driveExplorer(now);
  startSonarClock();
  driveMotors();
  draw(now);
  lcd_.pump(now);
}

void BrickApp::run() {
  nxtmapIrqEnable();
  for (;;) {
    const uint32_t before = ms_;
    loopOnce();
    // Nothing new happened during the pass: stop the processor clock until the next interrupt.
    if (ms_ == before) bus_.write(reg::kPmcScdr, 1u);
  }
}

void BrickApp::checkFailed(const char* file, int line, const char* what) {
  safety_.trip(MotorSafety::Reason::Check);
  runner_.abort();
  mode_ = Mode::Fault;
  screen_.clear();
  screen_.text(0, 0, "CHECK FAILED");
  const char* tail = file;
  for (const char* p = file; *p != 0; ++p) {
    if (*p == '/') tail = p + 1;
  }
  screen_.text(0, 8, tail);
  screen_.number(0, 16, static_cast<uint32_t>(line));
  screen_.text(0, 24, what);
  lcd_.refresh();
  nxtmapIrqEnable();
  for (;;) {
    lcd_.pump(ms_);
    bus_.write(reg::kPmcScdr, 1u);
  }
}

}  // namespace nxtmap::fw
