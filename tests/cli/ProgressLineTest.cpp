// ProgressLine: on a terminal one line rewritten in place; in a log a line at the start, at each tenth of the
// way and at the end, and a word when the work stopped short.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "host/cli/ProgressLine.hpp"

namespace nxtmap::cli {
namespace {

std::vector<std::string> linesOf(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

struct LogCase {
  size_t total;
  size_t ticks;                     // of one step each
  std::vector<std::string> expect;  // the lines written
};

class ProgressLineInALog : public ::testing::TestWithParam<LogCase> {};

TEST_P(ProgressLineInALog, WritesALineAtEachTenth) {
  const LogCase& k = GetParam();
  std::ostringstream out;
  {
    ProgressLine p(out, false, "runs", k.total);
    for (size_t i = 0; i < k.ticks; ++i) p.tick();
  }
  EXPECT_EQ(linesOf(out.str()), k.expect);
  EXPECT_EQ(out.str().find('\r'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Table, ProgressLineInALog,
    ::testing::Values(LogCase{100,
                              100,
                              {"[runs] 0 of 100", "[runs] 10 of 100", "[runs] 20 of 100", "[runs] 30 of 100",
                               "[runs] 40 of 100", "[runs] 50 of 100", "[runs] 60 of 100", "[runs] 70 of 100",
                               "[runs] 80 of 100", "[runs] 90 of 100", "[runs] 100 of 100"}},
                      LogCase{1800,
                              1800,
                              {"[runs] 0 of 1800", "[runs] 180 of 1800", "[runs] 360 of 1800", "[runs] 540 of 1800",
                               "[runs] 720 of 1800", "[runs] 900 of 1800", "[runs] 1080 of 1800", "[runs] 1260 of 1800",
                               "[runs] 1440 of 1800", "[runs] 1620 of 1800", "[runs] 1800 of 1800"}},
                      LogCase{3, 3, {"[runs] 0 of 3", "[runs] 1 of 3", "[runs] 2 of 3", "[runs] 3 of 3"}},
                      LogCase{0, 0, {"[runs] 0 of 0"}},
                      LogCase{10,
                              3,
                              {"[runs] 0 of 10", "[runs] 1 of 10", "[runs] 2 of 10", "[runs] 3 of 10",
                               "[runs] stopped at 3 of 10"}}));

TEST(ProgressLine, OnATerminalRewritesOneLineAndErasesItAtTheEnd) {
  std::ostringstream out;
  {
    ProgressLine p(out, true, "runs", 2);
    p.tick(1, "occ089");
    p.tick(1, "occ095");
  }
  EXPECT_EQ(out.str(), "\r\x1b[K[runs] 0 of 2\r\x1b[K[runs] 1 of 2: occ089\r\x1b[K[runs] 2 of 2: occ095\r\x1b[K");
}

TEST(ProgressLine, NamesWhatTheStepWas) {
  std::ostringstream out;
  {
    ProgressLine p(out, false, "experiments", 1);
    p.tick(1, "occ089");
  }
  EXPECT_EQ(linesOf(out.str()), (std::vector<std::string>{"[experiments] 0 of 1", "[experiments] 1 of 1: occ089"}));
}

}  // namespace
}  // namespace nxtmap::cli
