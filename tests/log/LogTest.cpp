// The host log: which messages print at which level, the line's form, the level names, NXTMAP_LOG.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "host/log/Log.hpp"

namespace nxtmap::log {
namespace {

// Captures every line for the test's lifetime and restores the level and stderr afterwards.
class Captured {
 public:
  Captured() : before_(level()) {
    setSink([this](const std::string& line) { lines.push_back(line); });
  }
  ~Captured() {
    setSink(nullptr);
    setLevel(before_);
  }
  std::vector<std::string> lines;

 private:
  Level before_;
};

void say(Level l, const char* area, int n) {
  switch (l) {
    case Level::Error: error(area, "n=%d", n); break;
    case Level::Warn: warn(area, "n=%d", n); break;
    case Level::Info: info(area, "n=%d", n); break;
    case Level::Debug: debug(area, "n=%d", n); break;
  }
}

TEST(Log, AMessagePrintsWhenItsLevelIsAtOrBelowTheLevelSet) {
  const Level all[] = {Level::Error, Level::Warn, Level::Info, Level::Debug};
  struct Case {
    Level set, message;
    bool printed;
  };
  const Case cases[] = {
      {Level::Error, Level::Error, true},  {Level::Error, Level::Warn, false}, {Level::Error, Level::Info, false},
      {Level::Error, Level::Debug, false}, {Level::Warn, Level::Error, true},  {Level::Warn, Level::Warn, true},
      {Level::Warn, Level::Info, false},   {Level::Warn, Level::Debug, false}, {Level::Info, Level::Error, true},
      {Level::Info, Level::Warn, true},    {Level::Info, Level::Info, true},   {Level::Info, Level::Debug, false},
      {Level::Debug, Level::Error, true},  {Level::Debug, Level::Warn, true},  {Level::Debug, Level::Info, true},
      {Level::Debug, Level::Debug, true},
  };
  ASSERT_EQ(std::size(cases), std::size(all) * std::size(all));
  for (const Case& c : cases) {
    Captured out;
    setLevel(c.set);
    EXPECT_EQ(enabled(c.message), c.printed) << levelName(c.set) << " / " << levelName(c.message);
    say(c.message, "house", 7);
    write(c.message, "emu", "%s", "w");
    const std::vector<std::string> want =
        c.printed ? std::vector<std::string>{std::string("[") + levelName(c.message) + "] house: n=7\n",
                                             std::string("[") + levelName(c.message) + "] emu: w\n"}
                  : std::vector<std::string>{};
    EXPECT_EQ(out.lines, want) << levelName(c.set) << " / " << levelName(c.message);
  }
}

TEST(Log, OneLinePerMessageWithTheLevelAndTheArea) {
  struct Case {
    Level level;
    const char* area;
    std::string message, line;
  };
  const Case cases[] = {
      {Level::Warn, "house", "room 3: end 2", "[warn] house: room 3: end 2\n"},
      {Level::Debug, "emu", "block 00100000 size 8\n", "[debug] emu: block 00100000 size 8\n"},
      {Level::Error, "link", "", "[error] link: \n"},
  };
  for (const Case& c : cases) EXPECT_EQ(formatLine(c.level, c.area, c.message), c.line);
  Captured out;
  setLevel(Level::Debug);
  const std::string longText(3000, 'x');
  debug("house", "%s|%zu", longText.c_str(), longText.size());
  ASSERT_EQ(out.lines.size(), 1u);
  EXPECT_EQ(out.lines[0], "[debug] house: " + longText + "|3000\n");
}

TEST(Log, LevelNamesAndNXTMAP_LOG) {
  struct Case {
    const char* text;
    std::optional<Level> level;
  };
  const Case cases[] = {{"error", Level::Error},   {"warn", Level::Warn},   {"warning", Level::Warn},
                        {"info", Level::Info},     {"debug", Level::Debug}, {"DEBUG", std::nullopt},
                        {"verbose", std::nullopt}, {"", std::nullopt},      {"3", std::nullopt}};
  for (const Case& c : cases) {
    EXPECT_EQ(parseLevel(c.text), c.level) << c.text;
    ::setenv("NXTMAP_LOG", c.text, 1);
    bool bad = false;
    const Level fromEnv = levelFromEnvironment(bad);
    EXPECT_EQ(fromEnv, c.level.value_or(Level::Warn)) << c.text;
    EXPECT_EQ(bad, !c.level && *c.text) << c.text;  // empty is the same as unset
  }
  ::unsetenv("NXTMAP_LOG");
  bool bad = true;
  EXPECT_EQ(levelFromEnvironment(bad), Level::Warn);
  EXPECT_FALSE(bad);
}

}  // namespace
}  // namespace nxtmap::log
