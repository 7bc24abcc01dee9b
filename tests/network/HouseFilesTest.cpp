#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/network/HouseFiles.hpp"
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
      {replaced("cells_a: [[3, 0]]", "cells_a: [[3, \"x\"]]"), "broken YAML"},
      {replaced("quarter_turns_clockwise: 1", "quarter_turns_clockwise: 5"), "0..3"},
      {replaced("resolution: 0.1", "resolution: -1"), "resolution"},
      {replaced("name: kitchen", "name: hall"), "two rooms"},
  };
  for (const Case& c : cases) {
    const HouseLoad l = tryWith(c.text);
    EXPECT_FALSE(l.network) << c.message;
    EXPECT_NE(l.error.find(c.message), std::string::npos) << l.error;
    EXPECT_EQ(l.error.find('\n'), std::string::npos);
  }
  EXPECT_TRUE(tryWith(good).network);
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
