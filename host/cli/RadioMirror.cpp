#include "host/cli/RadioMirror.hpp"

namespace nxtmap::cli {

// A fixed session id: the bytes, and so the brick's timing, are the same from run to run.
RadioMirror::RadioMirror() : session_(link::SessionConfig{0x4D495252u}) {}

bool RadioMirror::step(uint32_t ms, bool explored) {
  if (ms == lastMs_) return false;
  lastMs_ = ms;
  if (!radio_.fromBrick.empty()) {
    session_.receive(radio_.fromBrick.data(), radio_.fromBrick.size(), ms);
    radio_.fromBrick.clear();
  }
  const std::vector<uint8_t> out = session_.transmit(ms);
  radio_.toBrick.insert(radio_.toBrick.end(), out.begin(), out.end());
  if (session_.map().changes() != changes_) {
    changes_ = session_.map().changes();
    changedMs_ = ms;
  }
  return explored && ms >= changedMs_ + kQuietMs;
}

bool RadioMirror::follow(emu::EmulatedRun& run, uint64_t cycles, bool untilExplored) {
  const sim::SimRobot& r = run.brick().robot();
  if (!started_ && map().known() > 0) {
    started_ = true;
    statusesAtStart_ = session_.statusesReceived();
    start_ = ExplorerStart{sim::Vec2(r.xCm(), r.yCm()), r.headingDeg()};
  }
  const bool explored = untilExplored && run.readSymbolByte("g_explorerDone").value_or(0) == 1;
  const bool quiet = step(static_cast<uint32_t>(cycles / (emu::kMckHz / 1000)), explored);
  if (started_ && !offsetLooked_ && session_.statusesReceived() > statusesAtStart_) {
    // The first Status since the explorer began: its offset, with the robot where it stands as it arrives (it
    // reads on the spot first); a robot already gone from its start cell keeps the centre alone.
    const protocol::StatusMsg& s = *session_.status();
    offsetLooked_ = true;
    if (s.pose.cell == Cell{0, 0} && s.pose.heading == Dir::North) {
      start_.offsetKnown = true;
      start_.centreCm = sim::Vec2(r.xCm(), r.yCm());
      start_.headingDeg = r.headingDeg();
      start_.offsetXCm = s.offsetXMm / 10.0;
      start_.offsetYCm = s.offsetYMm / 10.0;
    }
  }
  return quiet;
}

}  // namespace nxtmap::cli
