// TimedProfile: where the instructions of the timed function's costliest call went (the sensor update
// the brick's budget is set for). Every block run inside a timed call is counted at its address; when a
// call returns and it cost more than any before, its counts are kept. `byFunction` sums them by the
// image's function symbols: a flat profile (each function's own instructions, interrupts included as
// their handlers). Owned by the Machine; only built when profiling is asked for (it slows every block
// inside a timed call down to the machine's full block path).
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "host/emu/ElfImage.hpp"

namespace nxtmap::emu {

struct FunctionCost {
  std::string name;           // demangled; "?" + address for code no function symbol covers
  uint64_t instructions = 0;  // in the costliest call
};

class TimedProfile {
 public:
  void beginCall() { current_.clear(); }
  void count(uint32_t blockAddress, uint64_t instructions) { current_[blockAddress] += instructions; }
  // The call that just returned cost `total` instructions.
  void endCall(uint64_t total);

  uint64_t worstTotal() const { return worstTotal_; }
  // The costliest call's instructions by function, most first.
  std::vector<FunctionCost> byFunction(const ElfImage& image) const;

 private:
  std::unordered_map<uint32_t, uint64_t> current_, worst_;  // block address -> instructions
  uint64_t worstTotal_ = 0;
};

// A profile as lines for people: the top `max` functions with their instructions and share.
std::string profileLines(const std::vector<FunctionCost>& costs, uint64_t total, size_t max);

}  // namespace nxtmap::emu
