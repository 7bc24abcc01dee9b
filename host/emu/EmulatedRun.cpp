#include "host/emu/EmulatedRun.hpp"

namespace nxtmap::emu {

EmulatedRun::EmulatedRun(const ElfImage& image, const sim::World& world, const EmulatedRunOptions& options)
    : EmulatedRun(image, sim::siteFromRaster(world), options) {}

EmulatedRun::EmulatedRun(const ElfImage& image, const sim::Site& site, const EmulatedRunOptions& options)
    : image_(image), options_(options) {
  BrickConfig c = options.brick;
  c.pressEnterAtS = options.pressEnterAtS;
  if (!options.timedFunction.empty() && image.symbol(options.timedFunction)) {
    c.machine.timedFunction = options.timedFunction;
    c.machine.profileTimed = options.profileWorstUpdate;
    timed_ = true;
  }
  brick_ = std::make_unique<Brick>(image, site, c);
}

std::optional<uint8_t> EmulatedRun::readSymbolByte(const std::string& name) const {
  const auto at = image_.symbol(name);
  uint8_t v = 0;
  if (!at || !brick_->machine().readByte(*at, v)) return std::nullopt;
  return v;
}

std::optional<uint32_t> EmulatedRun::readSymbolWord(const std::string& name) const {
  const auto at = image_.symbol(name);
  if (!at) return std::nullopt;
  uint32_t v = 0;
  for (uint32_t i = 0; i < 4; ++i) {
    uint8_t b = 0;
    if (!brick_->machine().readByte(*at + i, b)) return std::nullopt;
    v |= static_cast<uint32_t>(b) << (8 * i);
  }
  return v;
}

uint8_t ExportedMap::at(int x, int y) const {
  const int i = x - minX, j = y - minY;
  if (i < 0 || j < 0 || i >= width || j >= height) return 0;
  return states[static_cast<size_t>(j * width + i)];
}

std::optional<ExportedMap> EmulatedRun::exportedMap() const {
  constexpr uint32_t kMagic = 0x3150414D;  // "MAP1"
  constexpr int kMaxSide = 64;
  const auto at = image_.symbol("g_mapExport");
  if (!at) return std::nullopt;
  auto byte = [&](uint32_t off) {
    uint8_t b = 0;
    brick_->machine().readByte(*at + off, b);
    return b;
  };
  auto i16 = [&](uint32_t off) { return static_cast<int16_t>(byte(off) | (byte(off + 1) << 8)); };
  const uint32_t magic = static_cast<uint32_t>(byte(0)) | (static_cast<uint32_t>(byte(1)) << 8) |
                         (static_cast<uint32_t>(byte(2)) << 16) | (static_cast<uint32_t>(byte(3)) << 24);
  if (magic != kMagic) return std::nullopt;
  ExportedMap m;
  m.minX = i16(4);
  m.minY = i16(6);
  m.width = i16(8);
  m.height = i16(10);
  if (m.width < 0 || m.height < 0 || m.width > kMaxSide || m.height > kMaxSide) return std::nullopt;
  const int n = m.width * m.height;
  m.states.resize(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    m.states[static_cast<size_t>(i)] =
        static_cast<uint8_t>((byte(12 + static_cast<uint32_t>(i / 4)) >> (2 * (i % 4))) & 3u);
  return m;
}

EmulatedRunReport EmulatedRun::run() {
  EmulatedRunReport r;
  const auto doneAt = image_.symbol("g_explorerDone");
  const bool hasDone = doneAt.has_value();
  const Machine& machine = brick_->machine();
  bool pcSeen = false;
  brick_->runFor(options_.maxSeconds, [&] {
    if (options_.onEvent && options_.onEvent(brick_->machine().clock().now)) return true;
    if (options_.stopWhenPcLeaves) {
      const bool connected = brick_->blueCore().connected();
      if (connected) pcSeen = true;
      if (pcSeen && !connected) {
        r.pcLeft = true;
        return true;
      }
    }
    if (!options_.stopWhenExplored) return false;
    uint8_t d = 0;
    // Exactly 1: before start-up zeroes .bss the byte holds the 0xA5 paint.
    return hasDone && machine.readByte(*doneAt, d) && d == 1;
  });
  const Machine& m = brick_->machine();
  const MachineStats s = m.stats();
  r.fault = m.fault();
  r.finished = !r.fault && hasDone && readSymbolByte("g_explorerDone").value_or(0) == 1;
  if (r.fault) r.pcLeft = false;
  r.emulatedSeconds = secondsFromCycles(s.cycles);
  r.wallSeconds = s.wallSeconds;
  r.cpuSeconds = s.cpuSeconds;
  r.executed = s.executed;
  r.irqs = s.irqs;
  r.slices = s.slices;
  r.idles = s.idles;
  r.ram = m.ramUse();
  r.staticRamBudget = image_.symbol("__static_ram");
  r.maxBusy = s.maxBusy;
  if (timed_) {
    r.sensorUpdates = s.timedCalls;
    r.maxPerUpdate = s.maxTimed;
    if (const TimedProfile* p = m.timedProfile()) r.worstUpdate = p->byFunction(image_);
  } else {
    r.sensorUpdates = readSymbolWord("g_sensorUpdates").value_or(0);
  }
  r.avrGood = brick_->avr().goodFrames();
  r.avrBad = brick_->avr().badFrames();
  for (int p = 0; p < 4; ++p) r.pings += brick_->sensor(p).pings();
  r.drivenCm = brick_->drive().drivenCm();
  const BlueCore& bc = brick_->blueCore();
  r.btPortOpen = bc.portOpen();
  r.btConnected = bc.connected();
  r.btStreaming = bc.streaming();
  r.btToPc = bc.bytesToPc();
  r.btFromPc = bc.bytesFromPc();
  r.xCm = brick_->robot().xCm();
  r.yCm = brick_->robot().yCm();
  r.headingDeg = brick_->robot().headingDeg();
  return r;
}

}  // namespace nxtmap::emu
