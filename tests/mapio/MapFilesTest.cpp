// host/mapio: loading Moving AI and ROS map_server maps, saving ROS maps (round trip, thresholds,
// negate, labels, malformed files, atomic writes) and `nxtmap sim --save`.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "host/mapio/MapFiles.hpp"
#include "tests/cli/CliTestSupport.hpp"

namespace nxtmap::mapio {
namespace {

using cli::test::readFile;
using cli::test::runCli;
using cli::test::shellQuote;
using cli::test::TempDir;

// A P5 PGM with the given pixel values (maxval 255), row-major.
std::string pgm(int w, int h, const std::vector<int>& px) {
  std::string s = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  for (int v : px) s.push_back(static_cast<char>(v));
  return s;
}

std::string yaml(const std::string& extra, const std::string& image = "m.pgm", double occ = 0.65, double fre = 0.196,
                 int negate = 0) {
  return "image: " + image + "\nresolution: 0.05\norigin: [-1.5, 2.25, 0.5]\nnegate: " + std::to_string(negate) +
         "\noccupied_thresh: " + std::to_string(occ) + "\nfree_thresh: " + std::to_string(fre) + "\n" + extra;
}

OccupancyMap sampleMap() {
  OccupancyMap m(5, 3, Occupancy::Free, 0.1, MapOrigin{-0.25, 1.5, 0.1});
  m.set(0, 0, Occupancy::Occupied);
  m.set(4, 2, Occupancy::Unknown);
  m.set(2, 1, Occupancy::Occupied);
  m.set(3, 0, Occupancy::Unknown);
  EXPECT_TRUE(m.setLabel("chair", CellBlock{1, 1, 1, 1}));
  EXPECT_TRUE(m.setLabel("table", CellBlock{2, 0, 3, 2}));
  return m;
}

TEST(MapFiles, RoundTripKeepsCellsOriginResolutionAndLabels) {
  TempDir tmp("mapio_rt");
  const OccupancyMap m = sampleMap();
  std::string error;
  ASSERT_TRUE(saveRosMap(m, tmp.path("room.yaml"), error)) << error;
  const MapLoad back = loadMap(tmp.path("room.yaml"));
  ASSERT_TRUE(back.map) << back.error;
  EXPECT_EQ(*back.map, m);
  EXPECT_EQ(back.map->labels().at("table"), (CellBlock{2, 0, 3, 2}));
}

TEST(MapFiles, SavedFilesAreMapSaverStyleAndByteIdenticalOnResave) {
  TempDir tmp("mapio_bytes");
  std::string error;
  ASSERT_TRUE(saveRosMap(sampleMap(), tmp.path("room.yaml"), error)) << error;
  const std::string yaml1 = readFile(tmp.path("room.yaml"));
  const std::string pgm1 = readFile(tmp.path("room.pgm"));
  // Pixels: occupied 0, free 254, unknown 205; image row 0 = map row 0.
  const std::string header = "P5\n# CREATOR: nxtmap 0.100 m/pix\n5 3\n255\n";
  ASSERT_EQ(pgm1.substr(0, header.size()), header);
  const std::string px = pgm1.substr(header.size());
  ASSERT_EQ(px.size(), 15u);
  EXPECT_EQ(static_cast<unsigned char>(px[0]), 0);
  EXPECT_EQ(static_cast<unsigned char>(px[1]), 254);
  EXPECT_EQ(static_cast<unsigned char>(px[3]), 205);
  EXPECT_EQ(static_cast<unsigned char>(px[14]), 205);
  EXPECT_NE(yaml1.find("image: room.pgm\n"), std::string::npos);
  EXPECT_NE(yaml1.find("mode: trinary\n"), std::string::npos);
  EXPECT_NE(yaml1.find("negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"), std::string::npos);
  EXPECT_NE(yaml1.find("  chair: [1, 1]\n"), std::string::npos);

  const MapLoad back = loadMap(tmp.path("room.yaml"));
  ASSERT_TRUE(back.map) << back.error;
  ASSERT_TRUE(saveRosMap(*back.map, tmp.path("room.yaml"), error)) << error;
  EXPECT_EQ(readFile(tmp.path("room.yaml")), yaml1);
  EXPECT_EQ(readFile(tmp.path("room.pgm")), pgm1);
  // No temporary files are left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(tmp.path())) ++files;
  EXPECT_EQ(files, 2);
}

struct ThresholdCase {
  int pixel;
  double occupiedThresh, freeThresh;
  int negate;
  Occupancy expected;
};

TEST(MapFiles, TrinaryThresholdsAndNegate) {
  // occ = negate ? p/255 : 1 - p/255; occ > occupied -> Occupied, occ < free -> Free, else Unknown.
  const std::vector<ThresholdCase> cases = {
      {0, 0.65, 0.196, 0, Occupancy::Occupied},   {254, 0.65, 0.196, 0, Occupancy::Free},
      {255, 0.65, 0.196, 0, Occupancy::Free},     {205, 0.65, 0.196, 0, Occupancy::Unknown},
      {205, 0.65, 0.25, 0, Occupancy::Free},      {128, 0.65, 0.196, 0, Occupancy::Unknown},
      {89, 0.65, 0.196, 0, Occupancy::Occupied},  {90, 0.65, 0.196, 0, Occupancy::Unknown},
      {0, 0.65, 0.196, 1, Occupancy::Free},       {255, 0.65, 0.196, 1, Occupancy::Occupied},
      {205, 0.65, 0.196, 1, Occupancy::Occupied}, {100, 0.65, 0.196, 1, Occupancy::Unknown},
      {128, 0.5, 0.5, 0, Occupancy::Free},        {127, 0.5, 0.5, 0, Occupancy::Occupied},
      {0, 1.0, 0.0, 0, Occupancy::Unknown},
  };
  TempDir tmp("mapio_thr");
  for (const ThresholdCase& c : cases) {
    tmp.write("m.pgm", pgm(1, 1, {c.pixel}));
    const std::string y = tmp.write("m.yaml", yaml("", "m.pgm", c.occupiedThresh, c.freeThresh, c.negate));
    const MapLoad r = loadRosMap(y);
    ASSERT_TRUE(r.map) << r.error;
    EXPECT_EQ(r.map->at(0, 0), c.expected)
        << "pixel " << c.pixel << " occ " << c.occupiedThresh << " free " << c.freeThresh << " negate " << c.negate;
  }
}

TEST(MapFiles, ImageRowZeroIsTheTopRowAndOriginIsRead) {
  TempDir tmp("mapio_rows");
  tmp.write("m.pgm", pgm(2, 2, {0, 254, 254, 205}));
  const MapLoad r = loadRosMap(tmp.write("m.yaml", yaml("labels:\n  door: [1, 0]\n  rug: [0, 0, 2, 2]\n")));
  ASSERT_TRUE(r.map) << r.error;
  EXPECT_EQ(r.map->at(0, 0), Occupancy::Occupied);
  EXPECT_EQ(r.map->at(1, 0), Occupancy::Free);
  EXPECT_EQ(r.map->at(1, 1), Occupancy::Unknown);
  EXPECT_DOUBLE_EQ(r.map->resolutionM(), 0.05);
  EXPECT_EQ(r.map->origin(), (MapOrigin{-1.5, 2.25, 0.5}));
  EXPECT_EQ(r.map->labels().at("door"), (CellBlock{1, 0, 1, 1}));
  EXPECT_EQ(r.map->labels().at("rug"), (CellBlock{0, 0, 2, 2}));
}

struct BadCase {
  std::string name;
  std::string yamlText;
  std::string pgmText;
  std::string expected;  // part of the error
};

TEST(MapFiles, MalformedFilesGiveAClearError) {
  const std::string good = pgm(2, 2, {0, 254, 254, 205});
  const std::vector<BadCase> cases = {
      {"no image key", "resolution: 0.1\noccupied_thresh: 0.65\nfree_thresh: 0.2\n", good, "missing key 'image'"},
      {"no resolution", "image: m.pgm\noccupied_thresh: 0.65\nfree_thresh: 0.2\n", good, "missing key 'resolution'"},
      {"zero resolution", "image: m.pgm\nresolution: 0\noccupied_thresh: 0.65\nfree_thresh: 0.2\n", good,
       "'resolution' must be a number > 0"},
      {"text resolution", "image: m.pgm\nresolution: fine\noccupied_thresh: 0.65\nfree_thresh: 0.2\n", good,
       "'resolution' must be a number > 0"},
      {"thresholds swapped", yaml("", "m.pgm", 0.2, 0.65), good, "thresholds must satisfy"},
      {"negate 2", yaml("", "m.pgm", 0.65, 0.196, 2), good, "'negate' must be 0 or 1"},
      {"origin of two", "image: m.pgm\nresolution: 0.1\norigin: [0, 0]\noccupied_thresh: 0.65\nfree_thresh: 0.2\n",
       good, "'origin' must be [x, y, yaw]"},
      {"scale mode", yaml("mode: scale\n"), good, "mode 'scale' not supported"},
      {"missing image", yaml("", "nothere.pgm"), good, "cannot open image file"},
      {"not a pgm", yaml(""), "P6\n2 2\n255\nabcdefghijkl", "not a PGM image"},
      {"truncated pgm", yaml(""), "P5\n2 2\n255\n\x01", "m.pgm"},
      {"yaml list", "- 1\n- 2\n", good, "not a YAML mapping"},
      {"broken yaml", "image: [m.pgm\n", good, "m.yaml"},
      {"label outside", yaml("labels:\n  chair: [2, 0]\n"), good, "label 'chair' lies outside the 2x2 map"},
      {"label block outside", yaml("labels:\n  bed: [1, 1, 2, 1]\n"), good, "label 'bed' lies outside"},
      {"label of three", yaml("labels:\n  bed: [1, 1, 2]\n"), good, "must be [col, row] or [col, row, width, height]"},
      {"label not a number", yaml("labels:\n  bed: [a, 1]\n"), good, "not a whole number"},
      {"label bad name", yaml("labels:\n  9lives: [0, 0]\n"), good, "label name '9lives' is not valid"},
      {"labels list", yaml("labels: [1, 2]\n"), good, "labels must be a mapping"},
  };
  TempDir tmp("mapio_bad");
  for (const BadCase& c : cases) {
    tmp.write("m.pgm", c.pgmText);
    const MapLoad r = loadMap(tmp.write("m.yaml", c.yamlText));
    EXPECT_FALSE(r.map) << c.name;
    EXPECT_NE(r.error.find(c.expected), std::string::npos) << c.name << ": " << r.error;
    EXPECT_EQ(r.error.find('\n'), std::string::npos) << c.name << ": " << r.error;
  }
  EXPECT_NE(loadMap(tmp.path("absent.yaml")).error.find("cannot open file"), std::string::npos);
  EXPECT_NE(loadMap(tmp.write("m.txt", "x")).error.find("unknown map format"), std::string::npos);
}

TEST(MapFiles, MovingAiMapsLoadWithCrlfAndHaveNoUnknown) {
  TempDir tmp("mapio_mai");
  const MapLoad r = loadMap(tmp.write("a.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.@T\r\nGSW\r\n"));
  ASSERT_TRUE(r.map) << r.error;
  EXPECT_EQ(r.map->width(), 3);
  EXPECT_EQ(r.map->height(), 2);
  EXPECT_EQ(r.map->at(0, 0), Occupancy::Free);
  EXPECT_EQ(r.map->at(0, 1), Occupancy::Free);
  EXPECT_EQ(r.map->count(Occupancy::Occupied), 4u);
  EXPECT_EQ(r.map->count(Occupancy::Unknown), 0u);
  for (const std::string bad : {"type octile\nheight 2\nwidth 3\nmap\n...\n",
                                "type octile\nheight 1\nwidth 3\nmap\n.x.\n", "height 1\nwidth 1\nmap\n.\n", ""}) {
    const MapLoad b = loadMap(tmp.write("b.map", bad));
    EXPECT_FALSE(b.map) << bad;
    EXPECT_NE(b.error.find("b.map"), std::string::npos) << b.error;
  }
}

TEST(MapFiles, FailedSaveLeavesNothingAndExistingFilesUntouched) {
  TempDir tmp("mapio_atomic");
  std::string error;
  EXPECT_FALSE(saveRosMap(sampleMap(), tmp.path("missing/dir/room.yaml"), error));
  EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("missing")));
  EXPECT_FALSE(saveRosMap(sampleMap(), tmp.path("room.png"), error));
  EXPECT_NE(error.find("*.yaml"), std::string::npos);

  ASSERT_TRUE(saveRosMap(sampleMap(), tmp.path("room.yaml"), error)) << error;
  OccupancyMap other(2, 2, Occupancy::Free);
  ASSERT_TRUE(saveRosMap(other, tmp.path("room.yaml"), error)) << error;
  const MapLoad back = loadMap(tmp.path("room.yaml"));
  ASSERT_TRUE(back.map) << back.error;
  EXPECT_EQ(*back.map, other);
}

TEST(OccupancyMapLabels, NamesAndBlocksAreChecked) {
  OccupancyMap m(4, 4, Occupancy::Free);
  EXPECT_TRUE(m.setLabel("chair", CellBlock{3, 3, 1, 1}));
  EXPECT_TRUE(m.setLabel("Sofa_2-b", CellBlock{0, 0, 4, 4}));
  EXPECT_FALSE(m.setLabel("", CellBlock{}));
  EXPECT_FALSE(m.setLabel("null", CellBlock{}));
  EXPECT_FALSE(m.setLabel("a b", CellBlock{}));
  EXPECT_FALSE(m.setLabel("_x", CellBlock{}));
  EXPECT_FALSE(m.setLabel("big", CellBlock{1, 1, 4, 1}));
  EXPECT_FALSE(m.setLabel("neg", CellBlock{-1, 0, 1, 1}));
  EXPECT_FALSE(m.setLabel("flat", CellBlock{0, 0, 0, 1}));
  EXPECT_EQ(m.labels().size(), 2u);
}

TEST(SimSave, ExploredMapIsSavedInTheWorldFrame) {
  TempDir tmp("mapio_sim");
  const std::string out = tmp.path("explored.yaml");
  const auto r =
      runCli("sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --show none --save " + shellQuote(out));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const MapLoad m = loadMap(out);
  ASSERT_TRUE(m.map) << m.error;
  EXPECT_EQ(m.map->width(), 22);
  EXPECT_EQ(m.map->height(), 22);
  EXPECT_EQ(m.map->at(1, 20), Occupancy::Free);  // the start cell, in world coordinates
  EXPECT_GT(m.map->count(Occupancy::Free), 300u);
  EXPECT_GT(m.map->count(Occupancy::Occupied), 80u);

  const auto bad = runCli("sim worlds/seed-appendix-a/occupancy-089.map --start 1,20 --show none --save " +
                          shellQuote(tmp.path("x.png")));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--save must name a .yaml file"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(tmp.path("x.png")));
}

}  // namespace
}  // namespace nxtmap::mapio
