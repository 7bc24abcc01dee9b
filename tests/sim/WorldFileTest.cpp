// WorldFile: nxtmap's YAML rooms read from files and text, starts, surfaces and transforms as written; the rooms
// in worlds/rooms load with their furniture, start and transform.
#include "host/sim/WorldFile.hpp"

#include "tests/sim/RoomText.hpp"
#include "tests/sim/SimTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace nxtmap::sim {
namespace {

using test::room;
using test::TempDir;

std::string roomPath(const std::string& file) { return std::string(NXTMAP_SOURCE_DIR) + "/worlds/rooms/" + file; }

TEST(WorldFile, ReadingRefusesAMissingFileAndADirectoryNamingThem) {
  TempDir tmp("worldfile");
  for (const std::string& path : {tmp.path("absent.yaml"), tmp.path()}) {
    const WorldFileLoad load = readWorldFile(path);
    EXPECT_FALSE(load.world);
    EXPECT_EQ(load.error.rfind(path + ": ", 0), 0u) << load.error;
  }
}

TEST(WorldFile, ReadingAFileGivesTheSameWorldAsParsingItsTextNamedAfterTheFile) {
  TempDir tmp("worldfile");
  const WorldFileLoad load = readWorldFile(tmp.write("small-room.yaml", room("")));
  ASSERT_TRUE(load.world) << load.error;
  EXPECT_EQ(load.world->name, "small-room");
  EXPECT_EQ(load.world->scene->rings().size(), 1u);
  EXPECT_FALSE(load.world->hasStart);
}

TEST(WorldFile, TellsItsFilesFromRosMapsAndFromText) {
  EXPECT_TRUE(looksLikeWorldFile(room("")));
  EXPECT_FALSE(looksLikeWorldFile("image: m.pgm\nresolution: 0.1\n"));
  EXPECT_FALSE(looksLikeWorldFile("nxtmap_world: [1\n"));
  EXPECT_FALSE(looksLikeWorldFile("- nxtmap_world\n"));
}

struct YawCase {
  double yawDeg;      // file: counter-clockwise from +x
  double compassDeg;  // plane: clockwise from north
};

TEST(WorldFile, StartYawBecomesACompassHeading) {
  const YawCase cases[] = {{0, 90}, {90, 0}, {180, 270}, {-90, 180}, {45, 45}, {360, 90}, {-360, 90}, {100, 350}};
  for (const YawCase& c : cases) {
    const WorldFileLoad load =
        parseWorldFile(room("start: {x: 1.5, y: 0.5, yaw: " + std::to_string(c.yawDeg) + "}\n"), "w.yaml");
    ASSERT_TRUE(load.world) << load.error;
    EXPECT_TRUE(load.world->hasStart);
    EXPECT_NEAR(load.world->startHeadingDeg, c.compassDeg, 1e-9) << "yaw " << c.yawDeg;
    EXPECT_NEAR(load.world->startCm.x(), 150.0, 1e-9);
    EXPECT_NEAR(load.world->startCm.y(), -50.0, 1e-9);
  }
}

TEST(WorldFile, DefaultSurfacesAreHardForPolygonsAndWallsAndThinForCircles) {
  const WorldFileLoad load = parseWorldFile(
      room("obstacles:\n  - {polygon: [[1, 1], [2, 1], [2, 2]]}\n  - {circle: [3, 1], radius: 0.1}\n"
           "  - {wall: [[3, 2], [3.5, 2], [3.5, 2.5]]}\n  - {circle: [3, 2.5], radius: 0.1, surface: hard}\n"),
      "w.yaml");
  ASSERT_TRUE(load.world) << load.error;
  const Scene& s = *load.world->scene;
  ASSERT_EQ(s.rings().size(), 2u);
  ASSERT_EQ(s.discs().size(), 2u);
  ASSERT_EQ(s.walls().size(), 2u);  // a wall of three points is two segments
  EXPECT_EQ(s.rings()[0].surface, Surface::Hard);
  EXPECT_EQ(s.rings()[1].surface, Surface::Hard);
  EXPECT_EQ(s.discs()[0].surface, Surface::Thin);
  EXPECT_EQ(s.discs()[1].surface, Surface::Hard);
  EXPECT_EQ(s.walls()[1].surface, Surface::Hard);
  EXPECT_NEAR(s.discs()[0].radiusCm, 10.0, 1e-9);
  EXPECT_NEAR(s.walls()[1].b.x(), 350.0, 1e-9);
  EXPECT_NEAR(s.walls()[1].b.y(), -250.0, 1e-9);
}

TEST(WorldFile, FurnitureMayTouchTheWallsAndOneAnother) {
  const WorldFileLoad load =
      parseWorldFile(room("obstacles:\n  - {polygon: [[0, 0], [1, 0], [1, 1], [0, 1]]}\n"
                          "  - {polygon: [[1, 0], [2, 0], [2, 1], [1, 1]]}\n  - {polygon: [[2, 1], [3, 1], [3, 2]]}\n"),
                     "w.yaml");
  EXPECT_TRUE(load.world) << load.error;
}

TEST(WorldFile, TransformTurnsAndMovesTheRoomButNotTheStart) {
  // (1, 0) turned 90 degrees counter-clockwise is (0, 1); moved by (0.5, 0) it is (0.5, 1) m -> (50, -100) cm.
  const WorldFileLoad load = parseWorldFile(
      "nxtmap_world: 1\noutline: {polygon: [[0, 0], [1, 0], [1, 1], [0, 1]]}\n"
      "start: {x: 0, y: 0.5, yaw: 90}\ntransform: {rotate_deg: 90, offset: [0.5, 0]}\n",
      "w.yaml");
  ASSERT_TRUE(load.world) << load.error;
  const std::vector<Vec2>& ring = load.world->scene->rings()[0].points;
  ASSERT_EQ(ring.size(), 4u);
  EXPECT_NEAR(ring[1].x(), 50.0, 1e-9);
  EXPECT_NEAR(ring[1].y(), -100.0, 1e-9);
  EXPECT_NEAR(ring[2].x(), -50.0, 1e-9);  // (1, 1) -> (-1, 1) -> (-0.5, 1)
  EXPECT_NEAR(ring[2].y(), -100.0, 1e-9);
  EXPECT_NEAR(load.world->startCm.x(), 0.0, 1e-9);
  EXPECT_NEAR(load.world->startCm.y(), -50.0, 1e-9);
  EXPECT_NEAR(load.world->startHeadingDeg, 0.0, 1e-9);
}

struct RoomCase {
  const char* file;
  size_t rings, walls, discs;
  double startXCm, startYCm, headingDeg;
};

class WorldFileRoom : public ::testing::TestWithParam<RoomCase> {};

TEST_P(WorldFileRoom, LoadsWithItsFurnitureAndStart) {
  const RoomCase& c = GetParam();
  const WorldFileLoad load = readWorldFile(roomPath(c.file));
  ASSERT_TRUE(load.world) << load.error;
  const WorldSpec& w = *load.world;
  EXPECT_FALSE(w.name.empty());
  EXPECT_EQ(w.scene->rings().size(), c.rings);
  EXPECT_EQ(w.scene->walls().size(), c.walls);
  EXPECT_EQ(w.scene->discs().size(), c.discs);
  ASSERT_TRUE(w.hasStart);
  EXPECT_NEAR(w.startCm.x(), c.startXCm, 1e-9);
  EXPECT_NEAR(w.startCm.y(), c.startYCm, 1e-9);
  EXPECT_NEAR(w.startHeadingDeg, c.headingDeg, 1e-9);
  EXPECT_FALSE(w.scene->solidAt(w.startCm));
}

// Counts and starts read off the files by hand (outline + furniture polygons; curtain segments; legs).
INSTANTIATE_TEST_SUITE_P(Rooms, WorldFileRoom,
                         ::testing::Values(RoomCase{"living-room.yaml", 4, 0, 5, 240.0, -100.0, 0.0},
                                           RoomCase{"bedroom-curtain.yaml", 4, 4, 0, 120.0, -250.0, 90.0},
                                           RoomCase{"diagonal-wall.yaml", 4, 0, 4, 150.0, -150.0, 45.0},
                                           RoomCase{"square-turned.yaml", 1, 0, 0, 0.0, 0.0, 0.0}));

TEST(WorldFile, LivingRoomIsSolidInTheSofaAndTheLegsAndFreeBetweenThem) {
  const WorldFileLoad load = readWorldFile(roomPath("living-room.yaml"));
  ASSERT_TRUE(load.world) << load.error;
  const Scene& s = *load.world->scene;
  EXPECT_EQ(s.rings()[1].surface, Surface::Soft);  // the sofa
  EXPECT_EQ(s.discs()[0].surface, Surface::Thin);  // a table leg
  EXPECT_NEAR(s.discs()[0].radiusCm, 1.25, 1e-9);  // 2.5 cm across
  EXPECT_TRUE(s.solidAt(Vec2(225.0, -332.0)));     // the sofa's middle (2.25, 3.32) m
  EXPECT_TRUE(s.solidAt(Vec2(180.0, -180.0)));     // a leg's centre (1.8, 1.8) m
  EXPECT_FALSE(s.solidAt(Vec2(225.0, -200.0)));    // under the table, between its legs
  EXPECT_FALSE(s.solidAt(Vec2(400.0, -150.0)));    // the free right half of the room
  EXPECT_TRUE(s.solidAt(Vec2(500.0, -100.0)));     // beyond the right wall
  EXPECT_FALSE(s.solidAt(Vec2(225.0, -285.0)));    // 2 cm in front of the sofa
}

TEST(WorldFile, TurnedSquarePutsItsCornerWhereTheTransformSays) {
  const WorldFileLoad load = readWorldFile(roomPath("square-turned.yaml"));
  ASSERT_TRUE(load.world) << load.error;
  const std::vector<Vec2>& ring = load.world->scene->rings()[0].points;
  ASSERT_EQ(ring.size(), 4u);
  // Corner (1.5, 1.5) turned 10 degrees: (1.5 (cos - sin), 1.5 (sin + cos)) = (1.216739, 1.737684) m, plus
  // the offset (0.0666667, 0.0666667) m, y flipped, in cm.
  EXPECT_NEAR(ring[2].x(), 128.3406, 1e-4);
  EXPECT_NEAR(ring[2].y(), -180.4351, 1e-4);
  // The walls stand 10 degrees off the plane's axes: the bottom side rises 10 degrees (y up = -plane y).
  const Vec2 bottom = ring[1] - ring[0];
  EXPECT_NEAR(std::atan2(-bottom.y(), bottom.x()) * 180.0 / 3.14159265358979323846, 10.0, 1e-9);
  EXPECT_FALSE(load.world->scene->solidAt(Vec2(0.0, 0.0)));
  EXPECT_TRUE(load.world->scene->solidAt(Vec2(0.0, -175.0)));  // beyond the turned top wall
}

}  // namespace
}  // namespace nxtmap::sim
