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
  if (!started_ && map().known() > 0) {
    started_ = true;
    const sim::SimRobot& r = run.brick().robot();
    start_ = ExplorerStart{sim::Vec2(r.xCm(), r.yCm()), r.headingDeg()};
  }
  const bool explored = untilExplored && run.readSymbolByte("g_explorerDone").value_or(0) == 1;
  return step(static_cast<uint32_t>(cycles / (emu::kMckHz / 1000)), explored);
}

}  // namespace nxtmap::cli
