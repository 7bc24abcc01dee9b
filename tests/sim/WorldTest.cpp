#include "host/sim/World.hpp"

#include "tests/sim/SimTestSupport.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <limits>

namespace nxtmap::sim {
namespace {

using test::dataPath;
using test::TempDir;

const std::vector<std::string> kSmallRows = {"@@@@@@", "@.G.T@", "@..O.@", "@SW@@@"};

void expectMatchesRows(const World& w, const std::vector<std::string>& rows) {
  ASSERT_EQ(w.height(), static_cast<int>(rows.size()));
  for (int r = 0; r < w.height(); ++r) {
    ASSERT_EQ(w.width(), static_cast<int>(rows[static_cast<size_t>(r)].size()));
    for (int c = 0; c < w.width(); ++c) {
      const char ch = rows[static_cast<size_t>(r)][static_cast<size_t>(c)];
      EXPECT_EQ(w.blocked(c, r), ch != '.' && ch != 'G') << "col " << c << " row " << r;
    }
  }
}

TEST(WorldMovingAi, LoadsGoodFile) {
  const WorldLoad res = World::loadMovingAi(dataPath("small.map"), 0.2);
  ASSERT_TRUE(res.world) << res.error;
  EXPECT_EQ(res.error, "");
  EXPECT_EQ(res.world->name(), "small");
  EXPECT_DOUBLE_EQ(res.world->resolutionM(), 0.2);
  expectMatchesRows(*res.world, kSmallRows);
  EXPECT_TRUE(res.world->inside(5, 3));
  EXPECT_FALSE(res.world->inside(6, 0));
  EXPECT_FALSE(res.world->inside(0, -1));
  EXPECT_TRUE(res.world->blocked(-1, 1));
  EXPECT_TRUE(res.world->blocked(1, 4));
}

TEST(WorldMovingAi, ToleratesCrlf) {
  TempDir tmp;
  std::string text = "type octile\r\nheight 4\r\nwidth 6\r\nmap\r\n";
  for (const auto& r : kSmallRows) text += r + "\r\n";
  const WorldLoad res = World::loadMovingAi(tmp.write("crlf.map", text));
  ASSERT_TRUE(res.world) << res.error;
  EXPECT_DOUBLE_EQ(res.world->resolutionM(), 0.10);
  expectMatchesRows(*res.world, kSmallRows);
}

struct BadMap {
  const char* label;
  const char* text;
  const char* expectedError;
  int line;
};

class WorldMovingAiBad : public ::testing::TestWithParam<BadMap> {};

TEST_P(WorldMovingAiBad, RejectsWithClearError) {
  TempDir tmp;
  const std::string path = tmp.write("bad.map", GetParam().text);
  const WorldLoad res = World::loadMovingAi(path);
  EXPECT_FALSE(res.world);
  EXPECT_NE(res.error.find(GetParam().expectedError), std::string::npos) << res.error;
  EXPECT_NE(res.error.find(path + ":" + std::to_string(GetParam().line) + ":"), std::string::npos) << res.error;
}

INSTANTIATE_TEST_SUITE_P(
    Variants, WorldMovingAiBad,
    ::testing::Values(
        BadMap{"empty", "", "missing 'type'", 1}, BadMap{"noType", "height 1\nwidth 1\nmap\n.\n", "missing 'type'", 1},
        BadMap{"otherType", "type hex\nheight 1\nwidth 1\nmap\n.\n", "unsupported map type", 1},
        BadMap{"noHeight", "type octile\nwidth 1\nmap\n.\n", "missing 'height'", 3},
        BadMap{"noWidth", "type octile\nheight 1\nmap\n.\n", "missing 'width'", 3},
        BadMap{"noMap", "type octile\nheight 1\nwidth 1\n", "missing 'map'", 4},
        BadMap{"badHeader", "type octile\nheight 1\nwidht 1\nmap\n.\n", "unexpected header", 3},
        BadMap{"badNumber", "type octile\nheight x1\nwidth 1\nmap\n.\n", "bad height 'x1'", 2},
        BadMap{"zeroWidth", "type octile\nheight 1\nwidth 0\nmap\n", "width 0 out of range", 3},
        BadMap{"negHeight", "type octile\nheight -2\nwidth 1\nmap\n", "height -2 out of range", 2},
        BadMap{"hugeWidth", "type octile\nheight 1\nwidth 4097\nmap\n", "width 4097 out of range", 3},
        BadMap{"fewRows", "type octile\nheight 3\nwidth 2\nmap\n..\n..\n", "expected 3 map rows, found 2", 7},
        BadMap{"shortRow", "type octile\nheight 2\nwidth 2\nmap\n..\n.\n", "has 1 characters, expected width 2", 6},
        BadMap{"longRow", "type octile\nheight 2\nwidth 2\nmap\n...\n..\n", "has 3 characters", 5},
        BadMap{"unknownChar", "type octile\nheight 2\nwidth 2\nmap\n..\n.x\n", "unknown character 'x' at column 2", 6},
        BadMap{"extraRows", "type octile\nheight 1\nwidth 2\nmap\n..\n@@\n", "extra data after 1 map rows", 6}),
    [](const ::testing::TestParamInfo<BadMap>& p) { return std::string(p.param.label); });

// Expected per pixel of room6x4.pgm (values 0 / 205 / 254): 0 = occupied, 205 = unknown, 254 = free.
const std::vector<std::string> kRosPixels = {"000000", "0FFUF0", "0F0FF0", "FFFFFF"};

TEST(WorldRos, LoadsTrinaryP5WithTopRowFirst) {
  const WorldLoad res = World::loadRosYaml(dataPath("room6x4.yaml"));
  ASSERT_TRUE(res.world) << res.error;
  const World& w = *res.world;
  EXPECT_EQ(w.name(), "room6x4");
  EXPECT_DOUBLE_EQ(w.resolutionM(), 0.05);
  ASSERT_EQ(w.width(), 6);
  ASSERT_EQ(w.height(), 4);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 6; ++c) {
      // Free pixels are free; occupied and unknown are blocked.
      EXPECT_EQ(w.blocked(c, r), kRosPixels[static_cast<size_t>(r)][static_cast<size_t>(c)] != 'F')
          << "col " << c << " row " << r;
    }
  }
}

TEST(WorldRos, NegateInvertsAndP2Accepted) {
  const WorldLoad res = World::load(dataPath("room6x4_negate.yaml"));
  ASSERT_TRUE(res.world) << res.error;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 6; ++c) {
      // Negated: black (0) pixels are free, white (254) and unknown grey (205) are blocked.
      EXPECT_EQ(res.world->blocked(c, r), kRosPixels[static_cast<size_t>(r)][static_cast<size_t>(c)] != '0')
          << "col " << c << " row " << r;
    }
  }
}

struct BadYaml {
  const char* label;
  const char* yamlBody;  // appended after "image: <abs path>\n" unless it starts with '!'
  const char* expectedError;
};

class WorldRosBad : public ::testing::TestWithParam<BadYaml> {};

TEST_P(WorldRosBad, RejectsWithClearError) {
  TempDir tmp;
  const std::string body = GetParam().yamlBody;
  const std::string yaml = body[0] == '!' ? body.substr(1) : "image: " + dataPath("room6x4.pgm") + "\n" + body;
  const std::string path = tmp.write("bad.yaml", yaml);
  tmp.write("notpgm.pgm", "P6\n1 1\n255\nabc");
  const WorldLoad res = World::loadRosYaml(path);
  EXPECT_FALSE(res.world);
  EXPECT_NE(res.error.find(path), std::string::npos) << res.error;
  EXPECT_NE(res.error.find(GetParam().expectedError), std::string::npos) << res.error;
}

INSTANTIATE_TEST_SUITE_P(
    Variants, WorldRosBad,
    ::testing::Values(
        BadYaml{"noResolution", "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n", "missing key 'resolution'"},
        BadYaml{"noImage", "!resolution: 0.1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n", "missing key 'image'"},
        BadYaml{"scaleMode", "mode: scale\nresolution: 0.1\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
                "only trinary"},
        BadYaml{"zeroResolution", "resolution: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
                "'resolution' must be a number > 0"},
        BadYaml{"badThresholds", "resolution: 0.1\noccupied_thresh: 0.1\nfree_thresh: 0.5\n", "thresholds"},
        BadYaml{"missingImage", "!image: nothere.pgm\nresolution: 0.1\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
                "cannot open image"},
        BadYaml{"notPgm", "!image: notpgm.pgm\nresolution: 0.1\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
                "not a PGM"},
        BadYaml{"notYaml", "!image: [unclosed\n", "bad.yaml: "}),
    [](const ::testing::TestParamInfo<BadYaml>& p) { return std::string(p.param.label); });

TEST(WorldLoadDispatch, ByExtension) {
  EXPECT_TRUE(World::load(dataPath("small.map")).world);
  EXPECT_TRUE(World::load(dataPath("room6x4.yaml")).world);
  const WorldLoad unknown = World::load(dataPath("room6x4.pgm"));
  EXPECT_FALSE(unknown.world);
  EXPECT_NE(unknown.error.find("unknown world format"), std::string::npos) << unknown.error;
  const WorldLoad missing = World::load(dataPath("absent.map"));
  EXPECT_FALSE(missing.world);
  EXPECT_NE(missing.error.find("cannot open"), std::string::npos) << missing.error;
}

// The simulator's cells: whole centimetres, 4 .. 169 cm (World::kMinCellCm .. kMaxCellCm).
TEST(WorldResolution, OnlyWholeCentimetresTheRobotCanMapAreAccepted) {
  for (double ok : {0.04, 0.05, 0.1, 0.15, 0.2, 0.5, 1.0, 1.69}) {
    EXPECT_EQ(World::resolutionProblem(ok), "") << ok;
  }
  for (double bad : {0.0, -0.1, 0.004, 0.01, 0.03, 0.025, 0.105, 0.125, 1.7, 1e-300, 1e300,
                     std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const std::string why = World::resolutionProblem(bad);
    EXPECT_NE(why.find("is not one the simulator can use: its cells must be a whole number of centimetres, "
                       "4 .. 169 cm (0.04 .. 1.69 m)"),
              std::string::npos)
        << bad << ": " << why;
  }
}

struct BadWorldFile {
  const char* label;
  std::function<std::string(const TempDir&)> make;  // writes the files, returns the world's path
  const char* expected;
};

std::function<std::string(const TempDir&)> rosWorld(const std::string& resolution) {
  return [resolution](const TempDir& d) {
    return d.write("w.yaml", "image: " + dataPath("room6x4.pgm") + "\nresolution: " + resolution +
                                 "\norigin: [0, 0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  };
}

std::function<std::string(const TempDir&)> linkTo(const std::string& target, const std::string& name) {
  return [target, name](const TempDir& d) {
    std::filesystem::create_symlink(target, d.path(name));
    return d.path(name);
  };
}

class WorldLoadBad : public ::testing::TestWithParam<BadWorldFile> {};

TEST_P(WorldLoadBad, IsRefusedAtOnceWithAClearMessage) {
  TempDir tmp("world_bad");
  const std::string path = GetParam().make(tmp);
  const auto start = std::chrono::steady_clock::now();
  const WorldLoad res = World::load(path);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  EXPECT_FALSE(res.world);
  EXPECT_EQ(res.error.rfind(path + ": ", 0), 0u) << res.error;
  EXPECT_NE(res.error.find(GetParam().expected), std::string::npos) << res.error;
}

const char* const kNotSimulated = "is not one the simulator can use";

INSTANTIATE_TEST_SUITE_P(
    Variants, WorldLoadBad,
    ::testing::Values(BadWorldFile{"resolutionTiny", rosWorld("0.004"),
                                   "'resolution' 0.004 is out of range: it must be in 0.01 .. 10 m"},
                      BadWorldFile{"resolutionQuarterCentimetres", rosWorld("0.025"),
                                   "resolution 0.025 m is not one the simulator can use"},
                      BadWorldFile{"resolutionCentimetre", rosWorld("0.01"), kNotSimulated},
                      BadWorldFile{"resolutionBetweenCentimetres", rosWorld("0.125"), "resolution 0.125 m"},
                      BadWorldFile{"resolutionTooCoarse", rosWorld("2"), kNotSimulated},
                      BadWorldFile{"resolutionDenormal", rosWorld("1e-300"), "'resolution' 1e-300 is out of range"},
                      BadWorldFile{"resolutionHuge", rosWorld("1e300"), "'resolution' 1e+300 is out of range"},
                      BadWorldFile{"resolutionNegative", rosWorld("-0.1"), "'resolution' must be a number > 0"},
                      BadWorldFile{"resolutionNan", rosWorld(".nan"), "'resolution' must be a number > 0"},
                      BadWorldFile{"mapDevZero", linkTo("/dev/zero", "zero.map"), "is a device, not a regular file"},
                      BadWorldFile{"yamlDevZero", linkTo("/dev/zero", "zero.yaml"), "is a device, not a regular file"},
                      BadWorldFile{"mapFolder",
                                   [](const TempDir& d) {
                                     std::filesystem::create_directory(d.path("room.map"));
                                     return d.path("room.map");
                                   },
                                   "is a directory, not a file"},
                      BadWorldFile{"mapHuge",
                                   [](const TempDir& d) {
                                     const std::string path = d.write("huge.map", "type octile\n");
                                     EXPECT_EQ(::truncate(path.c_str(), static_cast<off_t>(kMaxMovingAiBytes) + 1), 0);
                                     return path;
                                   },
                                   "larger than 18 MiB, the largest file accepted"}),
    [](const ::testing::TestParamInfo<BadWorldFile>& p) { return std::string(p.param.label); });

TEST(WorldLoad, AMovingAiWorldNeedsAResolutionTheSimulatorCanUse) {
  const WorldLoad res = World::loadMovingAi(dataPath("small.map"), 0.004);
  EXPECT_FALSE(res.world);
  EXPECT_NE(res.error.find(kNotSimulated), std::string::npos) << res.error;
}

TEST(WorldLoad, TheLargestMovingAiFileIsRead) {
  TempDir tmp("world_large");
  // 4096 rows of 4096 cells with CRLF line ends: the largest world, within kMaxMovingAiBytes.
  std::string text = "type octile\r\nheight 4096\r\nwidth 4096\r\nmap\r\n";
  const std::string row = std::string(4096, '.') + "\r\n";
  for (int r = 0; r < 4096; ++r) text += row;
  ASSERT_LE(text.size(), kMaxMovingAiBytes);
  const WorldLoad res = World::load(tmp.write("big.map", text));
  ASSERT_TRUE(res.world) << res.error;
  EXPECT_EQ(res.world->width(), 4096);
}

TEST(WorldFromRows, MarksBlockedAndPadsShortRows) {
  const World w = World::fromRows({"#.@ ", "#."}, 0.25);
  EXPECT_EQ(w.width(), 4);
  EXPECT_EQ(w.height(), 2);
  EXPECT_DOUBLE_EQ(w.resolutionM(), 0.25);
  EXPECT_TRUE(w.blocked(0, 0));
  EXPECT_FALSE(w.blocked(1, 0));
  EXPECT_TRUE(w.blocked(2, 0));
  EXPECT_FALSE(w.blocked(3, 0));
  EXPECT_FALSE(w.blocked(3, 1));
  EXPECT_TRUE(w.blocked(4, 1));
}

}  // namespace
}  // namespace nxtmap::sim
