// What the brick keeps of a failed check's condition (checktext::brief): as much as its screen shows.
#include <gtest/gtest.h>

#include <string>

#include "common/check/Check.hpp"

namespace nxtmap {
namespace {

TEST(CheckText, TheBrickKeepsTheConditionsFirst25Characters) {
  static constexpr auto kShort = checktext::brief("turns <= 8");
  static constexpr auto kExact = checktext::brief("phase_ == Phase::Done&&ok");  // 25 characters
  static constexpr auto kLong = checktext::brief("stepMrad > 0 && sweepMrad >= 0 && 2 * sweepMrad / stepMrad < 9");
  static constexpr auto kEmpty = checktext::brief("");
  struct Case {
    const char* kept;
    size_t size;  // bytes the image keeps, with the terminating 0
    std::string expected;
  };
  const Case cases[] = {
      {kShort.text, sizeof kShort.text, "turns <= 8"},
      {kExact.text, sizeof kExact.text, "phase_ == Phase::Done&&ok"},
      {kLong.text, sizeof kLong.text, "stepMrad > 0 && sweepMrad"},
      {kEmpty.text, sizeof kEmpty.text, ""},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(std::string(c.kept), c.expected);
    EXPECT_EQ(c.size, std::string(c.kept).size() + 1) << c.expected;
  }
  EXPECT_EQ(checktext::kShownChars, 25);
}

}  // namespace
}  // namespace nxtmap
