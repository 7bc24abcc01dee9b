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

}  // namespace nxtmap::cli
