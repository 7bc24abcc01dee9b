// The real firmware (nxtmap-sim.elf in the emulated brick) takes a room map uploaded by the PC
// (MapChunk) and "you stand at pose P on it" (SetPose), in a frame that is not the one it started
// in (a quarter turn and an offset away): the PC's copy comes back equal to the upload, the brick
// reports P, and a path sent in the new frame drives the robot to the right cell of the world.
#include "EmuTestSupport.hpp"
#include "host/emu/Clock.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/link/Session.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/sim/World.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

TEST(EmulatedUpload, TheFirmwareTakesAnUploadedRoomAndAPoseInItsFrame) {
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  if (!std::filesystem::exists(elf)) GTEST_SKIP() << "no nxtmap-sim.elf";
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  ASSERT_TRUE(world.world) << world.error;

  // The robot starts at world (1, 20) facing north (up). The room frame of the upload: the robot
  // stands at (10, 10) facing east there, so the frame's +y is world west (origin world (11, 30)).
  const mapping::FrameTransform room(11, 30, sim::Heading::W);
  const Pose at{Cell{10, 10}, Dir::East};
  {
    int col = 0, row = 0;
    room.toWorld(at.cell, col, row);
    ASSERT_EQ(col, 1);
    ASSERT_EQ(row, 20);
  }
  const Bounds window{6, 6, 14, 14};
  std::vector<CellState> cells;
  for (int y = window.minY; y <= window.maxY; ++y) {
    for (int x = window.minX; x <= window.maxX; ++x) {
      int col = 0, row = 0;
      room.toWorld(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, col, row);
      cells.push_back(world.world->blocked(col, row) ? CellState::Occupied : CellState::Free);
    }
  }
  // Three cells ahead in the room frame (east there) = world (1, 17) (north of the start).
  const std::vector<Cell> path{Cell{10, 10}, Cell{11, 10}, Cell{12, 10}, Cell{13, 10}};

  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 1;
  o.brick.startRow = 20;
  o.brick.heading = sim::Heading::N;
  o.brick.link = &radio;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = 120;

  link::Session pc;
  enum class Phase { Connect, Echo, Drive, Done } phase = Phase::Connect;
  uint16_t poseSeq = 0;
  bool echoed = false, poseSeen = false, reached = false;
  uint32_t lastMs = 0;
  o.onEvent = [&](uint64_t cycles) {
    const auto ms = static_cast<uint32_t>(cycles / (kMckHz / 1000));
    if (ms == lastMs) return false;
    lastMs = ms;
    if (!radio.fromBrick.empty()) {
      pc.receive(radio.fromBrick.data(), radio.fromBrick.size(), ms);
      radio.fromBrick.clear();
    }
    const std::vector<uint8_t> sent = pc.transmit(ms);
    radio.toBrick.insert(radio.toBrick.end(), sent.begin(), sent.end());
    if (!pc.connected()) return false;
    if (phase == Phase::Connect) {
      pc.uploadMap(window, cells, 1);
      poseSeq = pc.setPose(at);
      phase = Phase::Echo;
    } else if (phase == Phase::Echo && pc.acknowledged(poseSeq) && pc.pose() && pc.pose()->cell == at.cell &&
               pc.pose()->heading == at.heading && pc.map().known() == cells.size()) {
      echoed = true;
      poseSeen = true;
      pc.followPath(path, 3);
      phase = Phase::Drive;
    } else if (phase == Phase::Drive && pc.pathProgress() && pc.pathProgress()->pathId == 3 &&
               pc.pathProgress()->state != protocol::PathState::Following &&
               pc.pathProgress()->state != protocol::PathState::None) {
      reached = pc.pathProgress()->state == protocol::PathState::Reached;
      phase = Phase::Done;
    }
    return phase == Phase::Done && pc.commandsDone() && pc.pose() && pc.pose()->cell == path.back();
  };
  EmulatedRun emulated(*load.image, *world.world, o);
  const EmulatedRunReport r = emulated.run();
  EXPECT_FALSE(r.fault) << r.fault.describe();
  std::printf("upload, pose and path done after %.1f emulated s (%.2f s wall)\n", r.emulatedSeconds, r.wallSeconds);
  EXPECT_TRUE(echoed && poseSeen) << "after " << r.emulatedSeconds << " s: " << pc.map().known() << " cells back";
  EXPECT_TRUE(reached) << "after " << r.emulatedSeconds << " s";
  // The PC's copy is the upload, cell for cell, in the room's frame.
  size_t differ = 0;
  for (int y = window.minY; y <= window.maxY; ++y) {
    for (int x = window.minX; x <= window.maxX; ++x) {
      const size_t i = static_cast<size_t>(y - window.minY) * static_cast<size_t>(window.width()) +
                       static_cast<size_t>(x - window.minX);
      if (pc.map().at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}) != cells[i]) ++differ;
    }
  }
  EXPECT_EQ(differ, 0u);
  // The robot is really at world (1, 17), facing north (the room frame's east).
  const double cellCm = world.world->resolutionM() * 100.0;
  EXPECT_EQ(static_cast<int>(std::floor(r.xCm / cellCm)), 1);
  EXPECT_EQ(static_cast<int>(std::floor(r.yCm / cellCm)), 17);
  EXPECT_TRUE(r.headingDeg < 20.0 || r.headingDeg > 340.0) << r.headingDeg;
  ASSERT_TRUE(pc.brickCounters().has_value());
  EXPECT_EQ(pc.brickCounters()->link.commandsRun, 3u);  // one chunk, SetPose, the path: each once
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
