// `sim` (sim::World::load) and `path` (mapio::loadMap) read a map file through the same reader: the same file
// gives the same cells, or the same refusal. (The simulator alone further refuses resolutions its robot
// cannot map, and labels play no part in its world: neither appears below.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/mapio/MapFiles.hpp"
#include "host/sim/World.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::mapio {
namespace {

using ::nxtmap::test::TempDir;

// 3 x 2 pixels, maxval 255: black, white, unknown grey / mid grey, light grey, dark grey.
const std::string kPgm = std::string("P5\n3 2\n255\n") + '\0' + '\xff' + '\xcd' + '\x80' + '\xe0' + '\x30';
const std::string kPgmAscii16 = "P2\n3 2\n65535\n0 65535 52685\n32896 57568 12336\n";

struct MapCase {
  const char* label;
  std::string yaml;
  std::string pgm = kPgm;
};

std::string keys(const std::string& extra, const std::string& negate = "0", const std::string& occ = "0.65",
                 const std::string& fre = "0.196") {
  return "image: m.pgm\nresolution: 0.05\nnegate: " + negate + "\noccupied_thresh: " + occ + "\nfree_thresh: " + fre +
         "\n" + extra;
}

std::vector<MapCase> cases() {
  return {
      {"plain", keys("origin: [-1.5, 2.25, 0.5]\n")},
      {"negated", keys("", "1")},
      {"negateTrue", keys("", "true")},
      {"wideUnknownBand", keys("", "0", "0.9", "0.05")},
      {"noUnknownBand", keys("", "0", "0.5", "0.5")},
      {"ascii16Bit", keys("mode: trinary\n"), kPgmAscii16},
      {"labelsIgnoredBySim", keys("labels:\n  door: [1, 0]\n")},
      {"originNan", keys("origin: [.nan, 0.0, 0.0]\n")},
      {"originText", keys("origin: [x, 0.0, 0.0]\n")},
      {"originFar", keys("origin: [1e9, 0.0, 0.0]\n")},
      {"negateTwo", keys("", "2")},
      {"modeList", keys("mode: [trinary]\n")},
      {"modeScale", keys("mode: scale\n")},
      {"imageList", "image: [m.pgm]\nresolution: 0.05\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"},
      {"thresholdsSwapped", keys("", "0", "0.2", "0.6")},
      {"thresholdText", keys("", "0", "high")},
      {"resolutionNan", "image: m.pgm\nresolution: .nan\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"},
      {"labelNotANumber", keys("labels:\n  door: [a, 0]\n")},
      {"labelOfThree", keys("labels:\n  door: [1, 0, 1]\n")},
      {"notAMapping", "- 1\n- 2\n"},
      {"truncatedImage", keys(""), "P5\n3 2\n255\n\x01"},
  };
}

TEST(MapLoadersAgree, SimAndPathReadTheSameYamlAlike) {
  TempDir tmp("loaders_agree");
  for (const MapCase& c : cases()) {
    SCOPED_TRACE(c.label);
    tmp.write("m.pgm", c.pgm);
    const std::string path = tmp.write("m.yaml", c.yaml);
    const sim::WorldLoad world = sim::World::load(path);
    const MapLoad map = loadMap(path);
    ASSERT_EQ(world.world.has_value(), map.map.has_value()) << "sim: " << world.error << "\npath: " << map.error;
    if (!map.map) {
      EXPECT_EQ(world.error, map.error);
      continue;
    }
    ASSERT_EQ(world.world->width(), map.map->width());
    ASSERT_EQ(world.world->height(), map.map->height());
    EXPECT_DOUBLE_EQ(world.world->resolutionM(), map.map->resolutionM());
    for (int r = 0; r < map.map->height(); ++r) {
      for (int col = 0; col < map.map->width(); ++col) {
        // The simulator blocks what the map does not know to be free.
        EXPECT_EQ(world.world->blocked(col, r), !map.map->isFree(col, r)) << "col " << col << " row " << r;
      }
    }
  }
}

TEST(MapLoadersAgree, SimAndPathReadTheSameMovingAiFileAlike) {
  TempDir tmp("loaders_agree_mai");
  const std::string path = tmp.write("a.map", "type octile\nheight 2\nwidth 3\nmap\n.@T\nGSW\n");
  const sim::WorldLoad world = sim::World::load(path);
  const MapLoad map = loadMap(path);
  ASSERT_TRUE(world.world) << world.error;
  ASSERT_TRUE(map.map) << map.error;
  EXPECT_DOUBLE_EQ(world.world->resolutionM(), map.map->resolutionM());
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(world.world->blocked(c, r), !map.map->isFree(c, r));
  }
  const std::string bad = tmp.write("b.map", "type octile\nheight 2\nwidth 3\nmap\n.@T\n");
  EXPECT_EQ(sim::World::load(bad).error, loadMap(bad).error);
}

}  // namespace
}  // namespace nxtmap::mapio
