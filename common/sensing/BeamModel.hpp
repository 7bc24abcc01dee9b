#pragma once
#include <cstdint>

namespace nxtmap {

// The NXT sonar's beam model: how likely a reading is given the range the map predicts along the beam.
// Defaults fit the simulator's `nxt` preset (see `nxtmap experiments --noise list`).
struct BeamParams {
  // Mixture weights, per mille, summing to 1000 (valid()):
  int16_t hitPerMille = 900;   // the echo of the expected target, gaussian about the expected reading
  int16_t shortPerMille = 50;  // something nearer: cross-talk (3..50 cm), a thing off the map; exponential
  int16_t maxPerMille = 30;    // no echo although a target was in reach (specular loss past 35-60 deg)
  int16_t randPerMille = 20;   // a wild reading (nxt: 2 %), uniform over 0..randomMaxCm
  // Spread of the hit, mm, >= 5: 1 cm fixed per pose, +-0.5 cm per ping, the whole-cm reading and the
  // map's cells and the localiser's 5 cm bins (a wall is rarely on a cell face exactly): about 2 cm.
  int16_t hitSigmaMm = 20;   // 5..200
  int16_t shortMeanCm = 30;  // mean of the short readings' exponential, cm, 1..1000
  // The sensor's linear error: reading = true * scalePer10k / 10000 + biasMm (nxt: 0.9757 x + 1.88 cm).
  int16_t scalePer10k = 9757;
  int16_t biasMm = 19;
  int16_t reliableCm = 160;   // a target this near (true cm) always echoes ...
  int16_t limitCm = 260;      // ... and never this far; linear between
  int16_t randomMaxCm = 254;  // wild readings: any of 0..randomMaxCm cm

  constexpr bool valid() const {
    return hitPerMille >= 0 && shortPerMille >= 0 && maxPerMille >= 0 && randPerMille >= 0 &&
           hitPerMille + shortPerMille + maxPerMille + randPerMille == 1000 && hitSigmaMm >= 5 && hitSigmaMm <= 200 &&
           shortMeanCm >= 1 && shortMeanCm <= 1000 && scalePer10k > 0 && reliableCm > 0 && limitCm > reliableCm &&
           randomMaxCm > 0 && randomMaxCm < kNoEchoCm();
  }
  static constexpr int16_t kNoEchoCm() { return 255; }
};

// BeamModel (Probabilistic Robotics 6.3; AMCL's beam model): p(z | z*), a mixture of
//   hit:    w_hit * echo(z*) * N(z; reading(z*), sigma) over the whole cm z (density at z times 1 cm);
//   short:  w_short * exponential below reading(z*), normalised over 0..reading(z*) (all z when nothing is in
//           reach);
//   max:    no echo: w_max + w_hit * (1 - echo(z*));
//   random: w_rand / (randomMaxCm + 1) for each z in 0..randomMaxCm;
// where echo(z*) = 1 up to reliableCm, 0 from limitCm (and for "nothing in reach"), linear between.
// The gaussian is not renormalised over the readable range (its mass below 0 cm is negligible past a few cm).
//
// Units: a reading z is whole cm 0..254 or kNoEcho (255, the sensor's "no echo"); z* is the true range in whole
// cm from the sensor's face, >= 0, or kNothing (no target within reach). Probabilities are Q24 (kOne = 1.0),
// the mass of that whole cm. Costs are -ln p in 1/8 nat (kCostPerNat), rounded, 0..kMaxCost: a product of
// likelihoods is a sum of costs. Integers only, and in the per-reading path no 64-bit division (the ARM7TDMI has
// no divider): weights are held in Q16, divisions are 32-bit, products 64-bit.
class BeamModel {
 public:
  static constexpr int16_t kNoEcho = BeamParams::kNoEchoCm();
  static constexpr int16_t kNothing = -1;
  static constexpr uint32_t kOne = 1u << 24;
  static constexpr int kCostPerNat = 8;
  static constexpr uint8_t kMaxCost = 255;  // p = 0 (only with zero weights); otherwise at most ~80
  static constexpr int kMaxExpCost = 135;   // expQ24 is 0 past this many eighth-nats (e^-17)

  explicit BeamModel(const BeamParams& params = BeamParams{});
  const BeamParams& params() const { return params_; }

  // The reading a target at trueCm should give, mm (the linear error applied).
  int32_t expectedReadingMm(int16_t trueCm) const;
  // echo(z*) in per mille.
  int32_t echoPerMille(int16_t trueCm) const;

  // p(z | z*) in Q24, and its cost.
  uint32_t probability(int16_t zCm, int16_t trueCm) const;
  uint8_t cost(int16_t zCm, int16_t trueCm) const { return costOf(probability(zCm, trueCm)); }
  // The lowest cost of z over all z* (its best explanation): a reading's costs minus this are >= 0.
  uint8_t bestCost(int16_t zCm) const;

  // e^(-n/8) in Q24 (n eighth-nats, >= 0; 0 past kMaxExpCost), and its inverse: the cost of p (Q24), rounded.
  static uint32_t expQ24(int32_t n);
  static uint8_t costOf(uint32_t pQ24);

 private:
  uint32_t hitQ24(int16_t zCm, int32_t expectedMm) const;
  uint32_t shortQ24(int16_t zCm, int32_t expectedMm) const;  // expectedMm < 0: nothing in reach

  BeamParams params_;
  // Derived once: the weights in Q16, the gaussian's peak mass per cm and the random floor per cm in Q24.
  uint32_t hitW_ = 0, shortW_ = 0, maxW_ = 0;
  uint32_t hitPeakQ24_ = 0, randQ24_ = 0;
};

}  // namespace nxtmap
