// The brick's speaker end to end: LEGO's PLAY_TONE and STOP_SOUND_PLAYBACK direct commands, framed by hand
// from the Bluetooth Developer Kit's table ([length LE16][0x00][opcode][...]), sent over the emulated radio
// to the real firmware (nxtmap-sim.elf) in the emulated brick; the SSC model is watched from outside: the
// words it sends and its word time (MCK cycles per 32-bit word; 16 words are one period of the tone).
// Named EndToEnd: make test runs it from the Release build (0.4 s there; cheap enough to run under ASan too).
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/sim/World.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr double kCyclesPerMs = static_cast<double>(kMckHz) / 1000.0;
constexpr uint64_t kWordsPerPeriod = 16;

std::string firmwarePath() {
  if (const char* env = std::getenv("NXTMAP_FIRMWARE")) return env;
#ifdef NXTMAP_EMU_FIRMWARE_DIR
  const std::string p = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  return std::filesystem::exists(p) ? p : "";
#else
  return "";
#endif
}

std::string whyNotRun() { return firmwarePath().empty() ? "no nxtmap-sim.elf in this build" : ""; }

// A direct command that wants a reply: [len LE16][0x00][opcode][args] (push_back only: GCC 12 -O3 flags
// vector::insert of a short vector with -Warray-bounds).
std::vector<uint8_t> directCommand(uint8_t opcode, const std::vector<uint8_t>& args) {
  const size_t n = 2 + args.size();
  std::vector<uint8_t> f;
  f.push_back(static_cast<uint8_t>(n));
  f.push_back(static_cast<uint8_t>(n >> 8));
  f.push_back(0x00);
  f.push_back(opcode);
  for (uint8_t b : args) f.push_back(b);
  return f;
}
std::vector<uint8_t> playTone(uint16_t hz, uint16_t ms) {
  return directCommand(0x03, {static_cast<uint8_t>(hz), static_cast<uint8_t>(hz >> 8), static_cast<uint8_t>(ms),
                              static_cast<uint8_t>(ms >> 8)});
}
std::vector<uint8_t> stopSound() { return directCommand(0x0C, {}); }

// One command sent at `atMs` (emulated, once the stream is open); what the SSC did after it.
struct Cue {
  double atMs;
  std::vector<uint8_t> frame;
};
struct Trace {
  std::string error;
  std::vector<double> sentMs;  // when each cue went out
  // Every change of the SSC's word count: (time ms, words so far, cycles per word then).
  struct Sample {
    double ms;
    uint64_t words, wordCycles;
  };
  std::vector<Sample> samples;
  size_t replies = 0;  // [02][opcode][status 0] replies seen
  size_t okReplies = 0;
  // Words sent in [fromMs, toMs) and the first/last time the count changed there.
  uint64_t wordsBetween(double fromMs, double toMs, double* first = nullptr, double* last = nullptr) const {
    uint64_t before = 0, after = 0;
    bool seen = false;
    for (const Sample& s : samples) {
      if (s.ms < fromMs) before = after = s.words;
      if (s.ms >= fromMs && s.ms < toMs) {
        if (!seen && first) *first = s.ms;
        seen = true;
        after = s.words;
        if (last) *last = s.ms;
      }
    }
    return after - before;
  }
};

Trace runCues(const std::vector<Cue>& cues, double endMs) {
  Trace t;
  ElfLoad load = ElfImage::load(firmwarePath());
  if (!load.image) {
    t.error = "firmware: " + load.error;
    return t;
  }
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  if (!world.world) {
    t.error = "world: " + world.error;
    return t;
  }
  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 1;
  o.brick.startRow = 20;
  o.brick.heading = sim::Heading::N;
  o.brick.link = &radio;
  o.pressEnterAtS = -1.0;  // the robot rests: only the speaker makes the SSC move
  o.stopWhenExplored = false;
  o.maxSeconds = endMs / 1000.0 + 1.0;
  EmulatedRun* run = nullptr;
  size_t next = 0;
  uint64_t lastWords = 0;
  o.onEvent = [&](uint64_t cycles) {
    const double ms = static_cast<double>(cycles) / kCyclesPerMs;
    const Brick& b = run->brick();
    if (next < cues.size() && b.blueCore().streaming() && ms >= cues[next].atMs) {
      for (uint8_t byte : cues[next].frame) radio.toBrick.push_back(byte);
      t.sentMs.push_back(ms);
      ++next;
    }
    if (b.ssc().wordsSent() != lastWords) {
      lastWords = b.ssc().wordsSent();
      t.samples.push_back({ms, lastWords, b.ssc().wordCycles()});
    }
    return ms >= endMs;
  };
  EmulatedRun e(*load.image, *world.world, o);
  run = &e;
  const EmulatedRunReport r = e.run();
  if (r.fault) t.error = "fault: " + r.fault.describe();
  if (next < cues.size()) t.error = "the stream never opened for every cue";
  // Replies: [len LE16][02][opcode][status].
  for (size_t i = 0; i + 4 < radio.fromBrick.size();) {
    const size_t n = radio.fromBrick[i] | (radio.fromBrick[i + 1] << 8);
    if (n >= 3 && radio.fromBrick[i + 2] == 0x02 &&
        (radio.fromBrick[i + 3] == 0x03 || radio.fromBrick[i + 3] == 0x0C)) {
      ++t.replies;
      if (radio.fromBrick[i + 4] == 0) ++t.okReplies;
    }
    i += 2 + n;
  }
  return t;
}

TEST(SpeakerEndToEnd, PlayToneSendsTheDurationsPeriodsAtTheFrequencyThenFallsSilent) {
  if (const std::string why = whyNotRun(); !why.empty()) GTEST_SKIP() << why;
  struct Row {
    uint16_t hz, ms;
  };
  // Each tone alone in a run of its own would cost a boot each: one run, the tones 600 ms apart.
  const Row rows[] = {{1000, 200}, {440, 100}, {3000, 50}};
  std::vector<Cue> cues;
  for (size_t i = 0; i < std::size(rows); ++i) cues.push_back({600.0 + 600.0 * i, playTone(rows[i].hz, rows[i].ms)});
  const Trace t = runCues(cues, 600.0 + 600.0 * std::size(rows) + 200);
  ASSERT_EQ(t.error, "");
  ASSERT_EQ(t.sentMs.size(), std::size(rows));
  EXPECT_EQ(t.okReplies, std::size(rows));
  EXPECT_EQ(t.wordsBetween(0, t.sentMs[0]), 0u) << "the speaker is silent until asked";
  for (size_t i = 0; i < std::size(rows); ++i) {
    const Row& r = rows[i];
    double first = 0, last = 0;
    const uint64_t words = t.wordsBetween(t.sentMs[i], t.sentMs[i] + 550, &first, &last);
    // The duration's whole periods, 16 words each (LEGO: Hz x ms / 1000 periods).
    EXPECT_EQ(words, uint64_t{r.hz} * r.ms / 1000 * kWordsPerPeriod) << r.hz << " Hz";
    // At the frequency: 16 words per period, within half a divider step (MCK / (1024 x DIV) for an integer
    // DIV: a step is ~Hz^2 x 1024 / MCK: 20 Hz at 1 kHz, 190 Hz at 3 kHz).
    uint64_t wordCycles = 0;
    for (const auto& s : t.samples)
      if (s.ms >= first && s.ms <= last) wordCycles = s.wordCycles;
    ASSERT_GT(wordCycles, 0u);
    const double hz = static_cast<double>(kMckHz) / static_cast<double>(wordCycles * kWordsPerPeriod);
    EXPECT_NEAR(hz, r.hz, 0.5 * r.hz * r.hz * 1024.0 / static_cast<double>(kMckHz) + 0.5) << r.hz << " Hz";
    // For about the duration, starting within the radio's few ms of the command.
    EXPECT_LT(first - t.sentMs[i], 15.0) << r.hz << " Hz";
    EXPECT_NEAR(last - first, r.ms, 3.0 + r.ms * 0.01) << r.hz << " Hz";
  }
}

TEST(SpeakerEndToEnd, StopSoundPlaybackSilencesALongTone) {
  if (const std::string why = whyNotRun(); !why.empty()) GTEST_SKIP() << why;
  const Trace t = runCues({{600, playTone(440, 3000)}, {900, stopSound()}}, 1700);
  ASSERT_EQ(t.error, "");
  ASSERT_EQ(t.sentMs.size(), 2u);
  EXPECT_EQ(t.okReplies, 2u);
  double first = 0, last = 0;
  const uint64_t playing = t.wordsBetween(t.sentMs[0], t.sentMs[1], &first, &last);
  const double playedMs = t.sentMs[1] - first;
  EXPECT_NEAR(static_cast<double>(playing), 440.0 * kWordsPerPeriod * playedMs / 1000.0, 440.0 * 16 * 0.01)
      << "playing at 440 Hz until the stop arrives";
  double stoppedAt = 0;
  (void)t.wordsBetween(t.sentMs[1], 1700, nullptr, &stoppedAt);
  EXPECT_LT(stoppedAt - t.sentMs[1], 15.0) << "the stop is obeyed within the radio's few ms";
  EXPECT_EQ(t.wordsBetween(t.sentMs[1] + 20, 1700), 0u) << "nothing after STOP_SOUND_PLAYBACK";
}

}  // namespace
}  // namespace nxtmap::emu::test
