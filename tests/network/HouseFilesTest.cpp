#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/network/HouseFiles.hpp"
#include "host/network/HouseLimits.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::network {
namespace {

Cell C(int x, int y) { return Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Two rooms: a 5 x 4 room with walls around and an opening, and a second one turned a quarter.
HouseNetwork twoRooms() {
  HouseNetwork n;
  RoomNode a;
  a.name = "hall";
  a.map = RoomMap(-1, -1, 5, 4);
  for (int y = -1; y <= 2; ++y) {
    for (int x = -1; x <= 3; ++x) {
      const bool wall = x == -1 || x == 3 || y == -1 || y == 2;
      a.map.set(C(x, y), wall ? CellState::Occupied : CellState::Free);
    }
  }
  a.map.set(C(3, 0), CellState::Free);  // the doorway
  a.map.set(C(2, 1), CellState::Unknown);
  a.labels["chair"] = C(1, 1);
  RoomNode b;
  b.name = "kitchen";
  b.map = RoomMap(-2, -1, 4, 3);
  for (int y = -1; y <= 1; ++y) {
    for (int x = -2; x <= 1; ++x) b.map.set(C(x, y), CellState::Free);
  }
  b.map.set(C(1, 1), CellState::Occupied);
  b.toHouse = RoomTransform::fromPose(C(4, 0), Dir::East);
  n.addRoom(a);
  n.addRoom(b);
  n.addGateway(Gateway{0, 1, {C(3, 0)}, {C(0, -1)}});
  return n;
}

TEST(HouseFiles, SaveReloadSaveGivesTheSameBytes) {
  test::TempDir t("house_bytes");
  std::string e;
  ASSERT_TRUE(saveHouse(twoRooms(), 0.1, t.path("h1"), e)) << e;
  const HouseLoad l = loadHouse(t.path("h1"));
  ASSERT_TRUE(l.network) << l.error;
  EXPECT_DOUBLE_EQ(l.resolutionM, 0.1);
  const HouseNetwork& n = *l.network;
  ASSERT_EQ(n.rooms().size(), 2u);
  EXPECT_TRUE(n.rooms()[0].map == twoRooms().rooms()[0].map);
  EXPECT_TRUE(n.rooms()[1].map == twoRooms().rooms()[1].map);
  EXPECT_EQ(n.rooms()[1].toHouse, twoRooms().rooms()[1].toHouse);
  EXPECT_EQ(n.rooms()[0].labels.at("chair"), C(1, 1));
  ASSERT_EQ(n.gateways().size(), 1u);
  EXPECT_EQ(n.gateways()[0].cellsB, (std::vector<Cell>{C(0, -1)}));
  ASSERT_TRUE(saveHouse(n, l.resolutionM, t.path("h2"), e)) << e;
  for (const char* f : {"house.yaml", "hall.yaml", "hall.pgm", "kitchen.yaml", "kitchen.pgm"}) {
    EXPECT_EQ(slurp(t.path(std::string("h1/") + f)), slurp(t.path(std::string("h2/") + f))) << f;
  }
  // Saving over an existing house replaces it as a whole (nothing of the old one is left).
  HouseNetwork one;
  RoomNode r;
  r.name = "solo";
  r.map = RoomMap(0, 0, 1, 1);
  one.addRoom(r);
  ASSERT_TRUE(saveHouse(one, 0.1, t.path("h1"), e)) << e;
  EXPECT_FALSE(std::filesystem::exists(t.path("h1/hall.yaml")));
  EXPECT_TRUE(std::filesystem::exists(t.path("h1/solo.pgm")));
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(t.path())) entries += entry.is_directory() ? 1 : 0;
  EXPECT_EQ(entries, 2);  // h1 and h2, no staging directory left behind
}

// Reads a room's PGM by the documented map_server rules (trinary, negate 0, thresholds 0.65 / 0.196)
// and checks every cell against the room map: image row y is map row height-1-y from the origin.
TEST(HouseFiles, RoomMapsLoadWithMapServerSemantics) {
  test::TempDir t("house_ros");
  std::string e;
  const HouseNetwork h = twoRooms();
  ASSERT_TRUE(saveHouse(h, 0.1, t.path("h"), e)) << e;
  const std::string yaml = slurp(t.path("h/hall.yaml"));
  EXPECT_NE(yaml.find("image: hall.pgm"), std::string::npos);
  EXPECT_NE(yaml.find("origin: [-0.1, -0.1, 0]"), std::string::npos);  // lower-left cell (-1, -1) in metres
  EXPECT_NE(yaml.find("negate: 0"), std::string::npos);
  std::ifstream in(t.path("h/hall.pgm"), std::ios::binary);
  // Header tokens (comment lines skipped), then one whitespace byte, then the pixels.
  std::vector<std::string> tokens;
  while (tokens.size() < 4 && in) {
    std::string tok;
    in >> tok;
    if (!tok.empty() && tok[0] == '#') {
      std::string rest;
      std::getline(in, rest);
      continue;
    }
    tokens.push_back(tok);
  }
  in.get();
  ASSERT_EQ(tokens.size(), 4u);
  const std::string magic = tokens[0];
  const int w = std::stoi(tokens[1]), hgt = std::stoi(tokens[2]), maxval = std::stoi(tokens[3]);
  ASSERT_EQ(magic, "P5");
  ASSERT_EQ(w, 5);
  ASSERT_EQ(hgt, 4);
  std::vector<unsigned char> px(static_cast<size_t>(w * hgt));
  in.read(reinterpret_cast<char*>(px.data()), static_cast<std::streamsize>(px.size()));
  const RoomMap& m = h.rooms()[0].map;
  for (int y = 0; y < hgt; ++y) {
    for (int x = 0; x < w; ++x) {
      const double occ = 1.0 - px[static_cast<size_t>(y * w + x)] / static_cast<double>(maxval);
      const int value = occ > 0.65 ? 100 : (occ < 0.196 ? 0 : -1);
      // data[width*(height-y-1)+x]: map row (from the bottom) height-y-1 -> room cell.
      const Cell c = C(m.minX() + x, m.minY() + (hgt - y - 1));
      const int expected = m.at(c) == CellState::Occupied ? 100 : (m.at(c) == CellState::Free ? 0 : -1);
      EXPECT_EQ(value, expected) << x << "," << y;
    }
  }
}

TEST(HouseFiles, BrokenHousesGiveOneMessageAndNoNetwork) {
  test::TempDir t("house_bad");
  std::string e;
  ASSERT_TRUE(saveHouse(twoRooms(), 0.1, t.path("h"), e)) << e;
  const std::string good = slurp(t.path("h/house.yaml"));
  const auto tryWith = [&](const std::string& text) {
    std::ofstream(t.path("h/house.yaml"), std::ios::binary | std::ios::trunc) << text;
    return loadHouse(t.path("h"));
  };
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {"rooms: [unclosed", "broken YAML"},
      {"just text", "not an nxtmap house file"},
      {replaced("map: kitchen.yaml", "map: cellar.yaml"), "room 'kitchen'"},
      {replaced("rooms: [hall, kitchen]", "rooms: [hall, attic]"), "not in the house"},
      {replaced("rooms: [hall, kitchen]", "rooms: [hall, hall]"), "to itself"},
      {replaced("cells_a: [[3, 0]]", "cells_a: [[3, 0], [3, 1]]"), "same, non-zero number"},
      {replaced("cells_a: [[3, 0]]", "cells_a: [[0, -1]]"), "wall"},
      {replaced("cells_a: [[3, 0]]", "cells_a: [[3, \"x\"]]"), "gateway 0: cells_a [0] y must be a whole number"},
      {replaced("quarter_turns_clockwise: 1", "quarter_turns_clockwise: 5"), "0..3"},
      {replaced("resolution: 0.1", "resolution: -1"), "resolution"},
      {replaced("name: kitchen", "name: hall"), "two rooms"},
      // Numbers beyond the house's bounds (HouseLimits), each named.
      {replaced("resolution: 0.1", "resolution: .nan"), "resolution must be a number of metres in 0.001..10"},
      {replaced("resolution: 0.1", "resolution: 1e-300"), "resolution must be a number of metres in 0.001..10"},
      {replaced("{x: 4, y: 0,", "{x: 2147483647, y: 0,"),
       "room 'kitchen': to_house x must be a whole number in -8192..8192"},
      {replaced("{x: 4, y: 0,", "{x: 4, y: -8193,"),
       "room 'kitchen': to_house y must be a whole number in -8192..8192"},
      {replaced("{x: 4, y: 0,", "{x: 1e300, y: 0,"), "room 'kitchen': to_house x must be a whole number"},
      {replaced("{x: 4, y: 0,", "{x: 4.5, y: 0,"), "room 'kitchen': to_house x must be a whole number"},
      {replaced("quarter_turns_clockwise: 1", "quarter_turns_clockwise: 4294967297"), "quarter_turns_clockwise"},
      {replaced("chair: [1, 1]", "chair: [70000, 1]"),
       "room 'hall': label 'chair' x must be a whole number in -8192..8192"},
      {replaced("chair: [1, 1]", "chair: [1, -99999999999]"), "label 'chair' y must be a whole number"},
      {replaced("chair: [1, 1]", "chair: [40, 1]"), "label 'chair' at [40, 1] lies outside the room's map"},
      {replaced("cells_a: [[3, 0]]", "cells_a: [[3, 70000]]"), "gateway 0: cells_a [0] y must be a whole number"},
      {replaced("cells_b: [[0, -1]]", "cells_b: [[0, -1], [1e9, 0]]"),
       "gateway 0: cells_b [1] x must be a whole number"},
      {replaced("cells_a: [[3, 0]]", "cells_a: [[3000, 0]]"), "gateway 0: cells_a [3000, 0] lies outside room 'hall'"},
      {replaced("cells_b: [[0, -1]]", "cells_b: [[-11, -1]]"),
       "gateway 0: cells_b [-11, -1] lies outside room 'kitchen'"},
      // Rooms placed far apart: every number in range, the house frame too wide to merge.
      {replaced("{x: 4, y: 0,", "{x: 8000, y: 0,"), "the rooms span 8003 x 4 cells in the house frame, more than 2048"},
      {replaced("{x: 0, y: 0,", "{x: -8192, y: 8192,"), "more than 2048 a side"},
  };
  for (const Case& c : cases) {
    const HouseLoad l = tryWith(c.text);
    EXPECT_FALSE(l.network) << c.message;
    EXPECT_NE(l.error.find(c.message), std::string::npos) << l.error;
    EXPECT_EQ(l.error.find('\n'), std::string::npos);
  }
  EXPECT_TRUE(tryWith(good).network);
  // At the bounds: still a house.
  EXPECT_TRUE(tryWith(replaced("{x: 4, y: 0,", "{x: 2000, y: 0,")).network);
  EXPECT_TRUE(tryWith(replaced("cells_b: [[0, -1]]", "cells_b: [[-10, -1]]")).network);  // 8 cells beyond the map

  // A room map whose origin puts it far from its room's entrance (a far origin once wrote outside the
  // heap; one still in range built a 4 GB merged map).
  const std::string hallMap = slurp(t.path("h/hall.yaml"));
  const auto hallWith = [&](const std::string& origin) {
    std::string s = hallMap;
    const std::string from = "origin: [-0.1, -0.1, 0]";
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos);
    std::ofstream(t.path("h/hall.yaml"), std::ios::binary | std::ios::trunc) << s.replace(at, from.size(), origin);
    return loadHouse(t.path("h"));
  };
  const std::vector<Case> origins = {
      {"origin: [4000, 0, 0]", "room 'hall': its map's origin [4000, 0] m lies beyond cells -8192..8192"},
      {"origin: [0, -1e300, 0]", "room 'hall'"},
      {"origin: [819.1, 0, 0]",
       "room 'hall': its map (5 x 4 cells from cell 8191, 0) reaches beyond cells -8192..8192"},
      {"origin: [400, 0, 0]", "the rooms span"},
      {"origin: [0.05, 0, 0]", "not on the house's cell grid"},
  };
  for (const Case& c : origins) {
    const HouseLoad l = hallWith(c.text);
    EXPECT_FALSE(l.network) << c.text;
    EXPECT_NE(l.error.find(c.message), std::string::npos) << l.error;
    EXPECT_EQ(l.error.find('\n'), std::string::npos);
  }
  EXPECT_TRUE(hallWith("origin: [-0.1, -0.1, 0]").network);

  // house.yaml is read only as a regular file of at most 1 MiB; at most 256 rooms.
  const HouseLoad big = tryWith(good + "# " + std::string(kMaxHouseFileBytes, 'x') + "\n");
  EXPECT_FALSE(big.network);
  EXPECT_NE(big.error.find("larger than 1 MiB, the largest house file accepted"), std::string::npos) << big.error;
  std::string crowd = "format: nxtmap-house-1\nresolution: 0.1\nrooms:\n";
  for (int i = 0; i <= kMaxRooms; ++i) crowd += "  - {name: r" + std::to_string(i) + ", map: hall.yaml}\n";
  EXPECT_NE(tryWith(crowd).error.find("'rooms' lists 257 rooms, more than 256"), std::string::npos);
  std::filesystem::remove(t.path("h/house.yaml"));
  std::filesystem::create_directory(t.path("h/house.yaml"));
  EXPECT_NE(loadHouse(t.path("h")).error.find("is a directory"), std::string::npos);
  std::filesystem::remove(t.path("h/house.yaml"));
  tryWith(good);
  std::filesystem::remove(t.path("h/hall.pgm"));
  EXPECT_FALSE(loadHouse(t.path("h")).network);
  EXPECT_NE(loadHouse(t.path("nowhere")).error.find("no house file"), std::string::npos);
}

TEST(HouseFiles, SavingNeverClobbersOtherDirectoriesOrHalfWritesAHouse) {
  test::TempDir t("house_refuse");
  std::filesystem::create_directories(t.path("docs"));
  std::ofstream(t.path("docs/notes.txt")) << "mine";
  std::string e;
  EXPECT_FALSE(saveHouse(twoRooms(), 0.1, t.path("docs"), e));
  EXPECT_NE(e.find("neither empty nor a house"), std::string::npos);
  EXPECT_EQ(slurp(t.path("docs/notes.txt")), "mine");
  HouseNetwork bad = twoRooms();
  bad.rooms()[1].name = "no/slash";
  EXPECT_FALSE(saveHouse(bad, 0.1, t.path("h"), e));
  EXPECT_FALSE(std::filesystem::exists(t.path("h")));
  HouseNetwork broken = twoRooms();
  broken.addGateway(Gateway{0, 5, {C(0, 0)}, {C(0, 0)}});
  EXPECT_FALSE(saveHouse(broken, 0.1, t.path("h"), e));
  EXPECT_FALSE(std::filesystem::exists(t.path("h")));
}

}  // namespace
}  // namespace nxtmap::network
