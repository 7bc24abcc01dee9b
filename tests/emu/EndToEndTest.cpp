// Acceptance: the real firmware image (its published-geometry build nxtmap-sim.elf: 0.10 m cells, 5..100 cm)
// maps each of the 18 published rooms inside the emulator, and its final map equals, cell by cell, the map of
// the host-simulated run of the same core on the same world (host/mapping/MappingRun), which itself meets the
// foundation's bars (100 % detection, no wrong cell). One test per room, so ctest spreads them over the cores.
#include "EmuTestSupport.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/MappingRun.hpp"

#include <filesystem>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR
const cli::Suite& suite() {
  static const cli::Suite s = cli::loadSuite(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a");
  return s;
}

class EndToEnd : public ::testing::TestWithParam<int> {};

TEST_P(EndToEnd, FirmwareMapsThePublishedRoomLikeTheHostRun) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "18 whole rooms at emulation speed: make test runs these from the Release build";
#endif
  const std::string path = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "firmware has no published-geometry image " << path;
  ElfLoad load = ElfImage::load(path);
  ASSERT_TRUE(load.image) << load.error;
  if (!load.image->symbol("g_explorerDone") || !load.image->symbol("g_mapExport"))
    GTEST_SKIP() << "nxtmap-sim.elf lacks g_explorerDone / g_mapExport";
  const report::Scenario& sc = suite().scenarios.at(static_cast<size_t>(GetParam()));
  const sim::World& world = suite().world(sc);

  EmulatedRunOptions o;
  o.brick.startCol = sc.startCol;
  o.brick.startRow = sc.startRow;
  o.brick.heading = sim::Heading::N;
  o.maxSeconds = 3600.0;
  EmulatedRun emulated(*load.image, world, o);
  const EmulatedRunReport r = emulated.run();
  ASSERT_FALSE(r.fault) << r.fault.describe();
  ASSERT_TRUE(r.finished) << "not done after " << r.emulatedSeconds << " s";
  const auto map = emulated.exportedMap();
  ASSERT_TRUE(map.has_value()) << "g_mapExport has no MAP1 magic";

  mapping::MappingRun host(world, cli::scenarioConfig(sc, mapping::Strategy::Propagation, sim::NoiseProfile{}, 1));
  host.runToEnd();
  const mapping::FrameTransform frame(sc.startCol, sc.startRow, sim::Heading::N);
  int differ = 0, fwWrong = 0, hostWrong = 0;
  std::string first, picture;
  for (int row = 0; row < world.height(); ++row)
    for (int col = 0; col < world.width(); ++col) {
      const Cell c = frame.toExplorer(col, row);
      const auto fw = static_cast<CellState>(map->at(c.x, c.y));
      const CellState pc = host.belief(col, row);
      const bool occ = world.blocked(col, row);
      if (fw != CellState::Unknown && (fw == CellState::Occupied) != occ) ++fwWrong;
      if (pc != CellState::Unknown && (pc == CellState::Occupied) != occ) ++hostWrong;
      const char* sym = ".#?";
      picture += fw == pc ? (fw == CellState::Occupied ? '#'
                             : fw == CellState::Free   ? '.'
                                                       : ' ')
                          : (fw == CellState::Occupied ? 'X'
                             : fw == CellState::Free   ? 'o'
                                                       : '?');
      (void)sym;
      if (col + 1 == world.width()) picture += '\n';
      if (fw != pc) {
        if (differ++ == 0)
          first = "first at col " + std::to_string(col) + " row " + std::to_string(row) + ": firmware " +
                  std::to_string(static_cast<int>(fw)) + " host " + std::to_string(static_cast<int>(pc));
      }
    }
  EXPECT_EQ(fwWrong, 0) << sc.id << ": firmware cells contradicting the world";
  EXPECT_EQ(differ, 0) << sc.id << ": " << differ << " cells differ from the host run (host wrong: " << hostWrong
                       << "), " << first << "\n(X firmware occupied, o firmware free, ? firmware unknown where the host"
                       << " differs)\n"
                       << picture << "robot at x " << r.xCm << " y " << r.yCm << " heading " << r.headingDeg;
  RecordProperty("emulated_s", std::to_string(r.emulatedSeconds));
  RecordProperty("speed", std::to_string(r.speedRatio()));
}

INSTANTIATE_TEST_SUITE_P(PublishedRooms, EndToEnd, ::testing::Range(0, 18));
#endif

}  // namespace
}  // namespace nxtmap::emu::test
