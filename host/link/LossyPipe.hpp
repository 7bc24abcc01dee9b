// LossyPipe: one direction of a radio link that fails like the real one: each byte is dropped,
// corrupted (a random bit pattern xor-ed in) or duplicated with the given probabilities.
// Seeded: the same seed gives the same faults.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

namespace nxtmap::link {

struct LossConfig {
  double drop = 0.0;  // probability per byte, 0..1
  double corrupt = 0.0;
  double duplicate = 0.0;
  uint64_t seed = 1;
  // 5 % of all bytes damaged, a third each way.
  static LossConfig fivePercent(uint64_t seed) { return LossConfig{0.05 / 3, 0.05 / 3, 0.05 / 3, seed}; }
};

struct LossCounters {
  uint64_t bytes = 0, dropped = 0, corrupted = 0, duplicated = 0;
};

class LossyPipe {
 public:
  explicit LossyPipe(const LossConfig& config) : config_(config), rng_(config.seed) {}
  // The bytes as they arrive at the other end.
  std::vector<uint8_t> pass(const std::vector<uint8_t>& bytes);
  const LossCounters& counters() const { return counters_; }

 private:
  LossConfig config_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  LossCounters counters_;
};

}  // namespace nxtmap::link
