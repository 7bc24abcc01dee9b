#include "host/link/LossyPipe.hpp"

namespace nxtmap::link {

std::vector<uint8_t> LossyPipe::pass(const std::vector<uint8_t>& bytes) {
  std::vector<uint8_t> out;
  out.reserve(bytes.size() + 8);
  for (uint8_t b : bytes) {
    ++counters_.bytes;
    const double u = unit_(rng_);
    if (u < config_.drop) {
      ++counters_.dropped;
    } else if (u < config_.drop + config_.corrupt) {
      ++counters_.corrupted;
      out.push_back(static_cast<uint8_t>(b ^ static_cast<uint8_t>(1 + rng_() % 255)));
    } else if (u < config_.drop + config_.corrupt + config_.duplicate) {
      ++counters_.duplicated;
      out.push_back(b);
      out.push_back(b);
    } else {
      out.push_back(b);
    }
  }
  return out;
}

}  // namespace nxtmap::link
