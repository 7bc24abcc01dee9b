// A HouseExpo house mapped through the real firmware (nxtmap-sim.elf: the published robot's 10 cm cells,
// the brick's 64 x 64 grid) in the emulated brick over a damaged radio: 5 % of the bytes each way
// dropped, corrupted or duplicated, and a 3 s forced disconnect while the brick maps the second room.
// The PC's side is the console's own `explore house` (HouseExploration over a link::Session), stepped
// with the brick's emulated clock over an in-memory radio, so the run is repeatable. No button is
// pressed. Nothing may be lost: the house mapped (HouseExpoHouse::expectAHouse: rooms, gateways, plan
// rooms, a floor; compared with sim-house, printed), the last room's map on the PC equal to the brick's
// grid; no room started twice; no command run twice; the wheels the house learnt kept in flash. (The clean run
// goes through the console over TCP: HouseEndToEndTest.)
#include "EmuTestSupport.hpp"
#include "HouseExpoHouse.hpp"
#include "host/console/HouseExploration.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/FlashState.hpp"
#include "host/link/LossyPipe.hpp"
#include "host/link/Session.hpp"

#include <cstdio>
#include <filesystem>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

constexpr uint32_t kDisconnectMs = 3000;
constexpr uint32_t kSettleMs = 60000;    // after the house: the last counters may take this long on a bad link
constexpr uint32_t kMapQuietMs = 10000;  // after the house: no map change for this long (the brick stands still)

// The PC's end of the radio, stepped once per emulated millisecond: bytes through the lossy pipes,
// one forced disconnect, the house exploration polled.
class PcSide {
 public:
  explicit PcSide(MemoryLink& radio)
      : radio_(radio),
        pc_(link::SessionConfig{sessionId()}),
        up_(link::LossConfig::fivePercent(11)),
        down_(link::LossConfig::fivePercent(12)) {}

  // Returns true when the run may end (the house done and the brick's counters caught up).
  bool step(uint32_t ms) {
    disconnectOnce(ms);
    if (!disconnected_) exchange(ms);
    radio_.fromBrick.clear();  // bytes sent while the link is down are lost
    if (!pc_.connected() || !pc_.status()) return false;
    if (!started_) {
      house_.start(pc_, ms / 1000.0);
      started_ = true;
    }
    const std::string said = house_.poll(pc_, ms / 1000.0);
    if (!said.empty()) std::printf("%7.1f s: %s", ms / 1000.0, said.c_str());
    if (!house_.done()) return false;
    if (doneMs_ == 0) doneMs_ = ms;
    if (pc_.map().changes() != mapChanges_) {
      mapChanges_ = pc_.map().changes();
      mapChangedMs_ = ms;
    }
    // The brick resends a map change until it is acknowledged: a map quiet this long is the brick's.
    const bool mapQuiet = ms >= mapChangedMs_ + kMapQuietMs;
    const bool settled = mapQuiet && pc_.commandsDone() && pc_.brickCounters() &&
                         pc_.brickCounters()->link.commandsRun >= pc_.counters().commandsAcknowledged;
    return settled || ms >= doneMs_ + kSettleMs;
  }

  const link::Session& session() const { return pc_; }
  const console::HouseExploration& house() const { return house_; }
  bool disconnected() const { return forced_; }
  uint64_t damaged() const {
    const auto sum = [](const link::LossyPipe& p) {
      return p.counters().dropped + p.counters().corrupted + p.counters().duplicated;
    };
    return sum(up_) + sum(down_);
  }

 private:
  // The session id goes in every Hello: a fixed one (not the console's random pick) keeps the run's
  // bytes, and so the damage done to them, the same from run to run.
  static uint32_t sessionId() { return 0x5E550000u + static_cast<uint32_t>(HouseExpoHouse::seed()); }

  // While the brick maps the second room, the link drops for kDisconnectMs.
  void disconnectOnce(uint32_t ms) {
    if (!forced_ && pc_.status() && pc_.status()->roomId >= 2 && pc_.status()->mode == protocol::BrickMode::Exploring) {
      forced_ = disconnected_ = true;
      downAt_ = ms;
      radio_.pcConnected = false;
      radio_.toBrick.clear();
      pc_.linkLost();
    }
    if (disconnected_ && ms >= downAt_ + kDisconnectMs) {
      disconnected_ = false;
      radio_.pcConnected = true;
    }
  }

  void exchange(uint32_t ms) {
    if (!radio_.fromBrick.empty()) {
      const std::vector<uint8_t> bytes = down_.pass(radio_.fromBrick);
      pc_.receive(bytes.data(), bytes.size(), ms);
    }
    const std::vector<uint8_t> sent = pc_.transmit(ms);
    if (!sent.empty()) {
      const std::vector<uint8_t> bytes = up_.pass(sent);
      radio_.toBrick.insert(radio_.toBrick.end(), bytes.begin(), bytes.end());
    }
  }

  MemoryLink& radio_;
  link::Session pc_;
  link::LossyPipe up_, down_;
  console::HouseExploration house_;
  bool started_ = false, forced_ = false, disconnected_ = false;
  uint32_t downAt_ = 0, doneMs_ = 0;
  uint64_t mapChanges_ = 0;
  uint32_t mapChangedMs_ = 0;
};

// Cells where the PC's copy of the brick's map and the brick's own grid (g_mapExport) differ.
int cellsDiffering(const link::Session& pc, const std::optional<ExportedMap>& brick) {
  if (!brick) return -1;
  int differ = 0;
  for (int y = brick->minY; y < brick->minY + brick->height; ++y)
    for (int x = brick->minX; x < brick->minX + brick->width; ++x)
      differ += static_cast<CellState>(brick->at(x, y)) !=
                pc.map().at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
  return differ;
}

TEST(HouseLinkEndToEnd, FivePercentDamagedBytesAndADisconnectLoseNothingAndRunNothingTwice) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole house at emulation speed: make test runs this from the Release build";
#endif
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  if (!std::filesystem::exists(elf)) GTEST_SKIP() << "no nxtmap-sim.elf";
  const std::optional<HouseExpoHouse> h = HouseExpoHouse::load();
  ASSERT_TRUE(h);
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;

  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startPose = *h->site.start;
  o.brick.noise = *sim::noiseProfileByName("typical");
  o.brick.seed = HouseExpoHouse::seed();
  o.brick.link = &radio;
  o.pressEnterAtS = -1;  // the PC's house commands start everything
  o.stopWhenExplored = false;
  o.maxSeconds = 4 * 3600;
  PcSide pc(radio);
  uint32_t lastMs = 0;
  o.onEvent = [&](uint64_t cycles) {
    const auto ms = static_cast<uint32_t>(cycles / (kMckHz / 1000));
    if (ms == lastMs) return false;
    lastMs = ms;
    return pc.step(ms);
  };
  EmulatedRun emulated(*load.image, h->site, o);
  const EmulatedRunReport r = emulated.run();
  const link::Session& s = pc.session();
  const uint32_t run = s.brickCounters() ? s.brickCounters()->link.commandsRun : 0;
  const uint32_t duplicates = s.brickCounters() ? s.brickCounters()->link.duplicates : 0;
  std::printf(
      "damaged link: %.0f s emulated in %.0f s wall; %llu bytes damaged; commands %u run, %u received again "
      "and not run\n",
      r.emulatedSeconds, r.wallSeconds, static_cast<unsigned long long>(pc.damaged()), run, duplicates);

  EXPECT_FALSE(r.fault) << r.fault.describe();
  ASSERT_TRUE(pc.house().done()) << "the house was not finished: " << pc.house().progress() << " "
                                 << pc.house().stopped();
  EXPECT_TRUE(pc.disconnected()) << "the run must go through its forced disconnect";
  h->expectAHouse(pc.house().planner().network(), "damaged link");
  EXPECT_EQ(cellsDiffering(s, emulated.exportedMap()), 0) << "the last room on the PC is the brick's grid";
  ASSERT_TRUE(s.status());
  EXPECT_EQ(s.status()->roomId, pc.house().roomsMapped()) << "no room started twice (the brick's room counter)";
  EXPECT_EQ(run, s.counters().commandsAcknowledged) << "every command run once, none twice";
  EXPECT_GT(pc.damaged(), 100u) << "the link damaged too few bytes to prove anything";
  EXPECT_GT(duplicates, 0u) << "no command was received twice: the damage proved nothing";
  // Nothing was in flash: the first room measured the turns, and the house kept what its runs learnt.
  const std::optional<WheelCalibration> kept = storedWheels(emulated.brick().machine().flashContents());
  ASSERT_TRUE(kept) << "the house kept nothing of the wheels";
  std::printf("wheels in flash after the house: %s\n", wheelsText(*kept).c_str());
  EXPECT_FALSE(kept->turnsUnknown()) << wheelsText(*kept);
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
