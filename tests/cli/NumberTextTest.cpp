// Whole-string numbers: what a table field or a command-line value may be.
#include "host/report/NumberText.hpp"

#include <gtest/gtest.h>

#include <string>

namespace nxtmap::report {
namespace {

TEST(NumberText, WholeIntAcceptsOnlyAnIntAndLeavesTheValueOnRefusal) {
  const struct {
    const char* text;
    bool ok;
    int value;
  } rows[] = {{"0", true, 0},          {"20", true, 20},        {"-7", true, -7},        {"+3", true, 3},
              {"2147483647", true, 2147483647}, {"", false, 99},     {" 1", true, 1},     {"1 ", false, 99},
              {"1.5", false, 99},      {"12a", false, 99},      {"2147483648", false, 99}, {"x", false, 99}};
  for (const auto& r : rows) {
    int v = 99;
    EXPECT_EQ(parseWholeInt(r.text, v), r.ok) << "'" << r.text << "'";
    EXPECT_EQ(v, r.value) << "'" << r.text << "'";
  }
}

TEST(NumberText, FiniteDoubleRefusesTrailingTextAndInfinities) {
  const struct {
    const char* text;
    bool ok;
    double value;
  } rows[] = {{"1.5", true, 1.5}, {"-0.95", true, -0.95}, {"294", true, 294}, {"1e2", true, 100},
              {"", false, 9},     {"1.5x", false, 9},     {"inf", false, 9},  {"nan", false, 9},
              {"1e999", false, 9}};
  for (const auto& r : rows) {
    double v = 9;
    EXPECT_EQ(parseFiniteDouble(r.text, v), r.ok) << "'" << r.text << "'";
    EXPECT_DOUBLE_EQ(v, r.value) << "'" << r.text << "'";
  }
}

}  // namespace
}  // namespace nxtmap::report
