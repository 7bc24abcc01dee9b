// escapeForTerminal: what reaches the terminal from a hostile file name or field.
#include "host/report/TerminalText.hpp"

#include <gtest/gtest.h>

#include <string>

namespace nxtmap::report {
namespace {

struct Row {
  std::string in, out;
};

TEST(TerminalText, ControlBytesAndBrokenUtf8AreShownAsHex) {
  const Row rows[] = {
      {"plain name.map", "plain name.map"},
      {"two\nlines\r", "two lines "},
      {std::string("nul\0here", 8), "nul\\x00here"},
      {"\x1b[2J\x1b]0;pwned\x07", "\\x1b[2J\\x1b]0;pwned\\x07"},
      {"tab\there", "tab\\x09here"},
      {"del\x7f", "del\\x7f"},
      {"caf\xc3\xa9 \xe2\x86\x92 \xf0\x9f\x8f\xa0", "caf\xc3\xa9 \xe2\x86\x92 \xf0\x9f\x8f\xa0"},  // UTF-8 kept
      {"c1 \xc2\x9b"
       "31m",
       "c1 \\xc2\\x9b31m"},                        // U+009B CSI
      {"latin1 \xe9t\xe9", "latin1 \\xe9t\\xe9"},  // not UTF-8
      {"cut \xe2\x86", "cut \\xe2\\x86"},          // truncated
      {"overlong \xc0\xaf", "overlong \\xc0\\xaf"},
      {"surrogate \xed\xa0\x80", "surrogate \\xed\\xa0\\x80"},
      {"back\\slash", "back\\slash"},
  };
  for (const Row& r : rows) EXPECT_EQ(escapeForTerminal(r.in), r.out) << r.out;
}

}  // namespace
}  // namespace nxtmap::report
