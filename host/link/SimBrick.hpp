// SimBrick: a stand-in for the brick, on the PC. The common core's explorer drives the
// simulated robot (mapping::MappingRun) and the brick's own protocol code (BrickLink, MapSync)
// talks over the link, exactly the objects the firmware runs. Used to test the link end to end
// and by `nxtmap connect sim:WORLD` until the emulated brick runs the real firmware.
//
// Stand-in simplifications: paths are followed on the world's truth, one cell per cellMs,
// without sensing; a later Explore resumes from the explorer's own belief of its pose; map
// uploads (MapChunk) are acknowledged and counted but not loaded into the explorer's map.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "common/protocol/BrickLink.hpp"
#include "host/mapping/MappingRun.hpp"

namespace nxtmap::link {

struct SimBrickConfig {
  mapping::RunConfig run;
  uint32_t actionMs = 20;       // one explorer action (read / move / turn) every this many ms
  uint32_t cellMs = 100;        // path following: one cell every this many ms
  uint16_t batteryMillivolts = 7800;
  protocol::BrickLinkConfig link;
};

class SimBrick {
 public:
  SimBrick(const sim::World& world, const SimBrickConfig& config);

  void receive(const uint8_t* data, size_t size);
  // Up to maxBytes of what the brick sends now (whole frames are queued; bytes leave in order).
  std::vector<uint8_t> transmit(uint32_t nowMs, size_t maxBytes);
  // Carries out commands and moves the robot up to nowMs.
  void step(uint32_t nowMs);
  void linkLost();

  const RoomGrid& grid() const { return run_.explorer().map().grid(); }
  protocol::BrickMode mode() const { return mode_; }
  const protocol::BrickLink& link() const { return link_; }
  const mapping::MappingRun& run() const { return run_; }
  // Sequence numbers of every command carried out, in order (the test for "never twice").
  const std::vector<uint16_t>& executed() const { return executed_; }
  Pose pose() const;
  const protocol::PathProgressMsg& path() const { return path_; }
  uint32_t mapChunks() const { return mapChunks_; }

 private:
  void carryOut(const protocol::Command& c);
  void followOne();
  bool worldBlocked(Cell c) const;
  protocol::BrickReport report() const;

  SimBrickConfig config_;
  mapping::MappingRun run_;
  std::vector<uint8_t> shadow_;
  protocol::BrickLink link_;
  protocol::BrickMode mode_ = protocol::BrickMode::Idle;
  uint32_t nextActionMs_ = 0;
  std::optional<Pose> pathPose_;  // pose while/after following a path (the explorer does not move then)
  protocol::PathMsg pathMsg_;
  protocol::PathProgressMsg path_;
  std::vector<uint16_t> executed_;
  std::vector<uint8_t> txQueue_;
  uint32_t mapChunks_ = 0;
};

}  // namespace nxtmap::link
