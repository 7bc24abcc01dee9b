#include "host/bench/LegoRoundTripBench.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::bench {
namespace {

constexpr double kIdleTargetMs = 60, kDrivingTargetMs = 100;
constexpr double kEnterAtS = 4.0;    // idle before, exploring after
constexpr double kEndS = 40.0;       // emulated end of the measurement
constexpr double kTimeoutMs = 2000;  // a reply later than this is lost
// GET_BATTERY_LEVEL as the Bluetooth Developer Kit gives it: length 2 (LE16), type 0x00 (reply wanted),
// opcode 0x0B; the reply is [0x02][0x0B][status][millivolts LE16] behind its own length.
constexpr uint8_t kRequest[] = {0x02, 0x00, 0x00, 0x0B};

// Takes the whole telegrams off the front of `bytes`; true if one was the battery reply.
bool takeBatteryReply(std::vector<uint8_t>& bytes) {
  bool found = false;
  size_t at = 0;
  while (bytes.size() - at >= 2) {
    const size_t n = bytes[at] | (static_cast<size_t>(bytes[at + 1]) << 8);
    if (bytes.size() - at < 2 + n) break;
    found = found || (n == 5 && bytes[at + 2] == 0x02 && bytes[at + 3] == 0x0B);
    at += 2 + n;
  }
  bytes.erase(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
  return found;
}

enum class Phase { Idle, Exploring, Moving };  // before Enter; after it, the robot standing or moving
struct Sample {
  double ms;
  Phase phase;
};

struct Figures {
  size_t n = 0;
  double mean = 0, p95 = 0, max = 0;
};

Figures figures(std::vector<double> v) {
  Figures f;
  f.n = v.size();
  if (v.empty()) return f;
  std::sort(v.begin(), v.end());
  for (double x : v) f.mean += x;
  f.mean /= static_cast<double>(v.size());
  f.p95 = v[std::min(v.size() - 1, v.size() * 95 / 100)];
  f.max = v.back();
  return f;
}

}  // namespace

int runLegoRoundTripBench(const std::string& scenarioDir) {
  const char* env = std::getenv("NXTMAP_FIRMWARE");
  const std::string fw = env ? env : "build/firmware/nxtmap-sim.elf";
  std::printf("\nLEGO direct command round trip (GET_BATTERY_LEVEL), %s in the emulated brick, emulated clock:\n",
              fw.c_str());
  emu::ElfLoad load = emu::ElfImage::load(fw);
  sim::WorldLoad world = sim::World::load(scenarioDir + "/occupancy-120.map");
  if (!load.image || !world.world) {
    std::printf("  SKIPPED: %s\n", !load.image ? load.error.c_str() : world.error.c_str());
    return 1;
  }
  emu::MemoryLink radio;
  emu::EmulatedRunOptions o;
  o.brick.startCol = 1;
  o.brick.startRow = 20;
  o.brick.heading = sim::Heading::N;
  o.brick.link = &radio;
  o.pressEnterAtS = kEnterAtS;
  o.stopWhenExplored = false;
  o.maxSeconds = kEndS;
  std::vector<Sample> samples;
  size_t lost = 0, sent = 0;
  double sentMs = -1, nextMs = 0, drivenAtSend = 0;
  uint32_t spacing = 0;
  emu::EmulatedRun* run = nullptr;
  o.onEvent = [&](uint64_t cycles) {
    const double ms = static_cast<double>(cycles) * 1000.0 / static_cast<double>(emu::kMckHz);
    const emu::Brick& b = run->brick();
    const bool replied = takeBatteryReply(radio.fromBrick);
    if (sentMs >= 0 && replied) {
      const Phase phase = sentMs / 1000.0 < kEnterAtS           ? Phase::Idle
                          : b.drive().drivenCm() > drivenAtSend ? Phase::Moving
                                                                : Phase::Exploring;
      samples.push_back({ms - sentMs, phase});
      sentMs = -1;
    } else if (sentMs >= 0 && ms - sentMs > kTimeoutMs) {
      ++lost;
      sentMs = -1;
    }
    if (sentMs < 0 && b.blueCore().streaming() && ms >= nextMs && ms >= 500) {
      radio.toBrick.insert(radio.toBrick.end(), std::begin(kRequest), std::end(kRequest));
      sentMs = ms;
      drivenAtSend = b.drive().drivenCm();
      ++sent;
      spacing = (spacing + 17) % 61;  // 20..80 ms apart: every phase of the brick's own periods
      nextMs = ms + 20 + spacing;
    }
    return false;
  };
  emu::EmulatedRun e(*load.image, *world.world, o);
  run = &e;
  const emu::EmulatedRunReport r = e.run();
  std::vector<double> idle, moving, exploring;
  for (const Sample& s : samples) {
    (s.phase == Phase::Idle ? idle : s.phase == Phase::Moving ? moving : exploring).push_back(s.ms);
    if (s.phase == Phase::Moving) exploring.push_back(s.ms);
  }
  const Figures fi = figures(idle), fd = figures(moving), fe = figures(exploring);
  int missed = 0;
  auto line = [&](const char* what, const Figures& f, double target) {
    const bool ok = f.n > 0 && f.max <= target && lost == 0;
    if (!ok) ++missed;
    std::printf("  %-22s %5zu replies  mean %6.1f ms  p95 %6.1f ms  max %7.1f ms   target max <= %3.0f ms   %s\n", what,
                f.n, f.mean, f.p95, f.max, target, ok ? "PASS" : "MISS");
  };
  line("idle", fi, kIdleTargetMs);
  line("while driving", fd, kDrivingTargetMs);
  std::printf("  %-22s %5zu replies  mean %6.1f ms  p95 %6.1f ms  max %7.1f ms   (info: standing or moving)\n",
              "exploring, all", fe.n, fe.mean, fe.p95, fe.max);
  std::printf("  %zu requests, %zu lost (no reply within %.0f ms); robot drove %.0f cm in %.0f emulated s%s\n", sent,
              lost, kTimeoutMs, r.drivenCm, r.emulatedSeconds, r.fault ? " (FAULT)" : "");
  if (r.fault) std::printf("    fault: %s\n", r.fault.describe().c_str());
  return missed;
}

}  // namespace nxtmap::bench
