#include "firmware/app/BrickApp.hpp"

#include <new>

#include "common/check/Check.hpp"
#include "firmware/app/Isr.hpp"
#include "firmware/app/MapExport.hpp"

namespace nxtmap::fw {
namespace {
constexpr TachoDecoder::Pins kTachoPins[TachoDecoder::kMotors] = {
    {reg::kPinTachoA, reg::kPinDirA}, {reg::kPinTachoB, reg::kPinDirB}, {reg::kPinTachoC, reg::kPinDirC}};
constexpr uint32_t kBlinkMs = 500;      // robot pixel blink and status refresh
constexpr uint32_t kMapRedrawMs = 500;  // the map is redrawn at most this often, and only when it changed
constexpr uint32_t kButtonStableMs = 50;
constexpr uint16_t kAvrSilentTripMs = 100;
constexpr uint32_t kRadioPeriodMs = 50;
constexpr uint32_t kSoftI2cTickRc = reg::kMck / 2 / 28800;  // 3 ticks per bit at 9600 bit/s
}  // namespace

// Counts filtered readings fed to the explorer; the emulator times nxtmapSensorUpdate.
// Run-end markers for the emulator: g_explorerDone turns 1 when the explorer reports Done, after
// (in the NXTMAP_SIM_GEOMETRY image) the final map was copied to g_mapExport.
extern "C" {
volatile uint8_t g_explorerDone = 0;
#if defined(NXTMAP_SIM_GEOMETRY)
MapExport g_mapExport;
#endif
}

// One sensor update: a filtered reading through the pilot into the explorer (marking rules and
// the explorer's next decision), or one more slice of a decision (a Thought event). The emulator
// times this function from entry to return; g_sensorUpdates counts the readings.
extern "C" {
volatile uint32_t g_sensorUpdates = 0;
__attribute__((noinline)) DriveAction nxtmapSensorUpdate(Pilot* pilot, const DriveEvent* e) {
  const DriveAction a = pilot->step(*e);
  if (e->kind == DriveEvent::Kind::Range) g_sensorUpdates = g_sensorUpdates + 1;
  return a;
}
}

BrickApp::BrickApp()
    : tacho_(kTachoPins),
      ports_{{bus_, kSensorPortPins[0]},
             {bus_, kSensorPortPins[1]},
             {bus_, kSensorPortPins[2]},
             {bus_, kSensorPortPins[3]}},
      map_(storage_.map.view(), AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight()),
      planner_(storage_.travel.view(), AppExplorerStorage::kWidth(), AppExplorerStorage::kHeight()),
      explorerConfig_(config_.explorer()),
      link_(map_.grid(), shadow_, protocol::BrickLinkConfig{}),
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

Pose BrickApp::pose() const {
  if (poseFromPath_) return follower_.pose();
  if (explorer_ != nullptr) return explorer_->pose();
  return restPose_;
}

protocol::BrickReport BrickApp::report() const {
  protocol::BrickReport r;
  r.mode = mode_;
  r.pose = pose();
  if (pilot_ != nullptr) r.counters = pilot_->counters();
  r.batteryMillivolts = static_cast<uint16_t>(batteryMillivolts(avr_.status().batteryRaw));
  r.roomId = roomId_;
  r.roomEntry = Cell{0, 0};
  r.path = follower_.progress();
  return r;
}

void BrickApp::startExploring(Strategy s, uint32_t now) {
  if (mode_ == Mode::Exploring) return;
  safety_.clear();
  tacho_.clearFault();
  follower_.abort();
  if (pilot_ != nullptr && !pilot_->finished() && !poseFromPath_) {
    // Resume a stopped run: the action that was cut short carries on to where it was going.
    if (!runner_.resume(wheels(), now)) runner_.begin(pending_, wheels(), now);
  } else {
    // A new run on the map as it is (empty in a new room, or what earlier runs, paths and the PC's
    // map left), from where the robot stands.
    const Pose here = pose();
    poseFromPath_ = false;
    if (s == Strategy::Frontier)
      explorer_ = new (explorerBuf_) FrontierExplorer(map_, planner_, explorerConfig_);
    else
      explorer_ = new (explorerBuf_) PropagationExplorer(map_, planner_, explorerConfig_);
    pilot_ = new (pilotBuf_) Pilot(*explorer_, PilotConfig{});
    pending_ = pilot_->step(DriveEvent::startAt(here));
    runner_.begin(pending_, wheels(), now);
  }
  mapDirty_ = true;
  mode_ = Mode::Exploring;
}

void BrickApp::followPath(const protocol::PathMsg& path, uint32_t now) {
  if (mode_ == Mode::Exploring) stop();
  safety_.clear();
  tacho_.clearFault();
  const Pose here = pose();
  if (!follower_.start(path, here, config_.drive.cellMm)) return;  // not from where the robot stands
  poseFromPath_ = true;
  DriveAction first;
  if (follower_.next(nullptr, first)) {
    pending_ = first;
    runner_.begin(first, wheels(), now);
    mode_ = Mode::Following;
  }
}

void BrickApp::takeMapChunk(const protocol::MapChunkMsg& chunk) {
  // Chunk 0: the robot stays where it is on the PC's map (same frame); the next run starts there.
  if (chunk.chunkIndex == 0) {
    restAt(pose());
    map_.clear();
  } else {
    stop();
  }
  for (uint16_t i = 0; i < chunk.count; ++i) {
    const CellState st = chunk.state(i);
    if (st == CellState::Free)
      (void)map_.markVisited(chunk.cellOf(i));
    else if (st == CellState::Occupied)
      (void)map_.markBlocked(chunk.cellOf(i));
  }
  if (chunk.chunkIndex + 1 >= chunk.chunkCount) link_.mapRestarted();
  mapDirty_ = true;
}

void BrickApp::restAt(const Pose& p) {
  stop();
  restPose_ = p;        // e.g. the robot's cell in a room the PC just uploaded (SetPose), in that room's frame
  explorer_ = nullptr;  // the next run starts from there on the map as it is
  pilot_ = nullptr;
  poseFromPath_ = false;
  mapDirty_ = true;
}

void BrickApp::stop() {
  runner_.abort();
  follower_.abort();
  if (mode_ == Mode::Exploring || mode_ == Mode::Following) mode_ = Mode::Idle;
}

void BrickApp::newRoom() {
  restAt(Pose{});
  map_.clear();
  link_.mapRestarted();
  ++roomId_;
  mode_ = Mode::Idle;
}

void BrickApp::carryOut(const protocol::Command& c, uint32_t now) {
  switch (c.kind) {
    case protocol::CommandKind::Explore: startExploring(Strategy::Frontier, now); break;
    case protocol::CommandKind::Stop: stop(); break;
    case protocol::CommandKind::FollowPath: followPath(c.path, now); break;
    case protocol::CommandKind::MapChunk: takeMapChunk(c.chunk); break;
    case protocol::CommandKind::SetPose: restAt(c.pose); break;
  }
}

void BrickApp::driveRobot(uint32_t now) {
  DriveEvent e;
  if (!runner_.poll(wheels(), now, e)) return;
  driveMotors();  // the action is over: motors to rest before a possibly long explorer decision
  if (mode_ == Mode::Exploring) {
    const bool thinking = e.kind == DriveEvent::Kind::Range || e.kind == DriveEvent::Kind::Thought;
    pending_ = thinking ? nxtmapSensorUpdate(pilot_, &e) : pilot_->step(e);
    mapDirty_ = true;
    if (pending_.kind == DriveAction::Kind::Done || pilot_->finished()) {
      mode_ = Mode::Done;
#if defined(NXTMAP_SIM_GEOMETRY)
      g_mapExport.fill(map_.grid());
#endif
      g_explorerDone = 1;
      return;
    }
    runner_.begin(pending_, wheels(), now);
  } else if (mode_ == Mode::Following) {
    if (follower_.next(&e, pending_))
      runner_.begin(pending_, wheels(), now);
    else
      mode_ = Mode::Idle;
  }
}

void BrickApp::driveMotors() {
  AvrCommand& cmd = avr_.command();
  if (safety_.tripped()) return;  // the tick holds them at 0 with the brake on
  const bool moving = mode_ == Mode::Exploring || mode_ == Mode::Following;
  const int8_t left = moving ? runner_.power(0) : 0;
  const int8_t right = moving ? runner_.power(1) : 0;
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
  if (b == Button::Enter)
    startExploring(Strategy::Propagation, now);
  else if (b == Button::Right)
    startExploring(Strategy::Frontier, now);
  else if (b == Button::Exit)
    stop();
  else if (b == Button::Left)
    newRoom();
}

void BrickApp::serveRadio(uint32_t now) {
  const uint32_t epoch = bt_.linkEpoch();
  bt_.poll(now);
  if (bt_.linkEpoch() != epoch) link_.linkLost();
  uint8_t b;
  while (bt_.readByte(b)) link_.receive(b);
  protocol::Command c;
  while (link_.nextCommand(c)) carryOut(c, now);
  // Outgoing frames: one per pass while the link has some, then a pause of kRadioPeriodMs. Building
  // a frame scans the map (MapSync: ~0.45 M instructions, ~10 ms), too much work to repeat in every
  // 1 ms pass, and none while the wheels are driven so the motion control keeps its 1 ms rhythm.
  if (!bt_.streaming() || bt_.txSpace() < protocol::kMaxFrame) return;
  if (runner_.power(0) != 0 || runner_.power(1) != 0) return;
  if (!radioBurst_ && now - lastRadioMs_ < kRadioPeriodMs) return;
  lastRadioMs_ = now;
  protocol::Frame f;
  radioBurst_ = link_.transmit(now, report(), f);
  if (radioBurst_) (void)bt_.write(f.bytes, f.size);
}

void BrickApp::draw(uint32_t now) {
  if (now - lastDrawMs_ < kBlinkMs) return;
  lastDrawMs_ = now;
  blink_ = !blink_;
  const Pose p = pose();
  if (mapDirty_ && mapPage_ < 0 && now - lastMapDrawMs_ >= kMapRedrawMs) {
    mapDirty_ = false;
    lastMapDrawMs_ = now;
    mapPage_ = 0;  // drawMapPages() draws one band per loop pass
  } else if (mapPage_ < 0) {
    screen_.drawRobot(map_.grid(), p.cell, blink_);
  }
  const int x = Screen::kTextX;
  static const char* const kModes[] = {"IDLE", "MAP", "PATH", "DONE", "STOP"};
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
  screen_.text(x, 21, link_.connected() ? "PC OK" : (avr_.up() ? "AVR OK" : "AVR --"));
  if (pilot_ != nullptr) {
    const Counters c = pilot_->counters();
    screen_.clearLine(30);
    screen_.text(screen_.number(x, 30, c.cellsMoved), 30, " C");
    screen_.clearLine(37);
    screen_.text(screen_.number(x, 37, c.sensorRequests), 37, " R");
  }
  screen_.clearLine(44);
  screen_.text(screen_.number(x + 8, 44, roomId_), 44, "");
  screen_.text(x, 44, "R");
  if (safety_.tripped()) {
    static const char* const kWhy[] = {"", "CHECK", "ENCODER", "AVR", "SILENT"};
    screen_.clearLine(52);
    screen_.text(x, 52, kWhy[static_cast<int>(safety_.reason())]);
  }
  lcd_.refresh();
}

void BrickApp::drawMapPages() {
  if (mapPage_ < 0) return;
  const Pose p = pose();
  screen_.drawMapPage(map_.grid(), p.cell, p.heading, blink_, mapPage_);
  if (++mapPage_ == Screen::kMapSize / 8) {
    mapPage_ = -1;
    lcd_.refresh();
  }
}

void BrickApp::loopOnce() {
  const uint32_t now = ms_;
  safety_.feed(now);
  if (tacho_.fault()) safety_.trip(MotorSafety::Reason::Encoder);
  const bool moving = mode_ == Mode::Exploring || mode_ == Mode::Following;
  if (moving && avr_.silentMs() > kAvrSilentTripMs) safety_.trip(MotorSafety::Reason::AvrLink);
  if (safety_.tripped() && moving) {
    runner_.abort();
    follower_.abort();
    mode_ = Mode::Fault;
  }
  serveRadio(now);
  readButtons(now);
  if (mode_ == Mode::Exploring || mode_ == Mode::Following) driveRobot(now);
  startSonarClock();
  driveMotors();
  draw(now);
  drawMapPages();
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
    if (ms_ == last && !bt_.rxPending()) bus_.write(reg::kPmcScdr, 1u);
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
