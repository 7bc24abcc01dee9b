#include "common/math/IntRound.hpp"

#include <gtest/gtest.h>

namespace nxtmap {
namespace {

TEST(IntRound, DividesToTheNearestIntegerWithTiesAwayFromZero) {
  const struct {
    int64_t n, d, expected;
  } table[] = {
      {0, 7, 0},
      {6, 4, 2},
      {5, 4, 1},
      {-5, 4, -1},
      {-6, 4, -2},
      {7, 2, 4},
      {-7, 2, -4},
      {1, 3, 0},
      {-1, 3, 0},
      {2, 3, 1},
      {-2, 3, -1},
      // A sweep step of 87 mrad told through a turn error of -2 %: 87 / 0.98 = 88.8 (truncated: 88).
      {87000000, 980000, 89},
      // Ranges of the pose tracker's products: 64-bit without overflow.
      {4000000000000LL, 1000000, 4000000},
      {-4000000000001LL, 2, -2000000000001LL},
  };
  for (const auto& t : table) EXPECT_EQ(divRound(t.n, t.d), t.expected) << t.n << " / " << t.d;
}

}  // namespace
}  // namespace nxtmap
