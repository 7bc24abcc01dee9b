// RadioMirror: a PC listening to the emulated brick over an in-memory radio, as the console would: it says
// Hello, keeps the copy of the brick's map the brick streams (link::Session's MirrorMap) and sends nothing
// else. `nxtmap emulate` scores that copy: the map a user gets is the one that came over the radio.
// Stepped with the brick's emulated clock (once per emulated millisecond), so a run stays repeatable.
#pragma once

#include <cstdint>
#include <optional>

#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/link/Session.hpp"
#include "host/sim/Scene.hpp"

namespace nxtmap::cli {

// The robot's true pose when the brick's explorer began (centre, plane cm; compass heading, degrees) and, once a
// Status told it while the robot still stood in its start cell facing the start heading, where the brick believed
// its centre lay from that cell's centre (cm along the explorer's x and y, StatusMsg's offset).
struct ExplorerStart {
  sim::Vec2 centreCm{0.0, 0.0};
  double headingDeg = 0.0;
  bool offsetKnown = false;
  double offsetXCm = 0.0, offsetYCm = 0.0;
};

class RadioMirror {
 public:
  RadioMirror();
  // The brick's end of the radio (BrickConfig::link).
  emu::LinkEndpoint* endpoint() { return &radio_; }
  // One exchange at emulated millisecond `ms` (a repeated ms does nothing). Returns true once the map
  // has been quiet for kQuietMs after `explored` turned true: the brick's last changes have arrived.
  bool step(uint32_t ms, bool explored);
  // The same for `run` at its cycle count (EmulatedRunOptions::onEvent), `explored` read from the firmware
  // (g_explorerDone) unless the run ends on its time limit only; notes where the robot stood when the first
  // map cells came (the start's sweep over, the explorer begun).
  bool follow(emu::EmulatedRun& run, uint64_t cycles, bool untilExplored);
  const ExplorerStart& explorerStart() const { return start_; }
  const link::MirrorMap& map() const { return session_.map(); }
  // The brick's last Status (where it believes it stands, its mode, ...); none before one arrived.
  const std::optional<protocol::StatusMsg>& status() const { return session_.status(); }
  // The brick's last Counters (what it counts and what it learnt of its wheels), if one arrived.
  const std::optional<protocol::CountersMsg>& brickCounters() const { return session_.brickCounters(); }
  // A map change unacknowledged is sent again by the brick: this long without one, the copy is whole.
  static constexpr uint32_t kQuietMs = 5000;

 private:
  emu::MemoryLink radio_;
  link::Session session_;
  uint32_t lastMs_ = UINT32_MAX;
  uint64_t changes_ = 0;
  uint32_t changedMs_ = 0;
  bool started_ = false;
  uint64_t statusesAtStart_ = 0;  // statuses received before the first map cells
  bool offsetLooked_ = false;     // the first Status since then was looked at (ExplorerStart::offsetKnown or not)
  ExplorerStart start_;
};

}  // namespace nxtmap::cli
