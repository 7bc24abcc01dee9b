#pragma once
#include <cstdint>

namespace nxtmap {

// sin a and cos a in per mille for a in mrad, |a| <= 1600 (about 92 deg): their series to the a^7 and a^8 terms,
// nested (Horner) in 32 bits, each step rounded towards zero; within 1.1 per mille there. Integer only (the
// brick has no floating point). For the geometry of a body turned part way (ThreePointTurn).
constexpr int32_t sinPerMille(int32_t a) {
  const int32_t x2 = a * a / 100;  // a^2 in 1e-4 rad^2 (at most 25,600); the terms below in 1e-4
  int32_t s = 10000 - x2 / 42;     // 1 - x^2/42
  s = 10000 - x2 * s / 200000;     // 1 - x^2/20 (...)
  s = 10000 - x2 * s / 60000;      // 1 - x^2/6 (...)
  return a * s / 10000;
}
constexpr int32_t cosPerMille(int32_t a) {
  const int32_t x2 = a * a / 100;
  int32_t c = 10000 - x2 / 56;
  c = 10000 - x2 * c / 300000;
  c = 10000 - x2 * c / 120000;
  c = 10000 - x2 * c / 20000;
  return c / 10;
}
static_assert(sinPerMille(0) == 0 && sinPerMille(524) == 500 && sinPerMille(1571) == 999 && sinPerMille(-1000) == -841,
              "sinPerMille: sin 30 deg, 90 deg (the series falls short), -1 rad");
static_assert(cosPerMille(0) == 1000 && cosPerMille(1047) == 500 && cosPerMille(1571) == 0 && cosPerMille(-1000) == 540,
              "cosPerMille: cos 60 deg, 90 deg, -1 rad");

}  // namespace nxtmap
