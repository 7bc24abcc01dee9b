// WorldFile: nxtmap's YAML rooms. Bad documents are refused with one line naming the file, the element and
// the problem; the rooms in worlds/rooms load with their furniture, start and transform as written.
#include "host/sim/WorldFile.hpp"

#include "tests/sim/SimTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace nxtmap::sim {
namespace {

using test::TempDir;

const std::string kRoom = "nxtmap_world: 1\noutline:\n  polygon: [[0, 0], [4, 0], [4, 3], [0, 3]]\n";

// The 4 x 3 m room with `more` appended (obstacles:, start:, ...).
std::string room(const std::string& more) { return kRoom + more; }

std::string roomPath(const std::string& file) { return std::string(NXTMAP_SOURCE_DIR) + "/worlds/rooms/" + file; }

struct BadWorld {
  const char* label;
  std::string text;
  const char* expected;  // part of the message
};

class WorldFileBad : public ::testing::TestWithParam<BadWorld> {};

TEST_P(WorldFileBad, IsRefusedWithOneLineNamingTheFileAndTheProblem) {
  const WorldFileLoad load = parseWorldFile(GetParam().text, "w.yaml");
  EXPECT_FALSE(load.world);
  EXPECT_EQ(load.error.rfind("w.yaml:", 0), 0u) << load.error;
  EXPECT_NE(load.error.find(GetParam().expected), std::string::npos) << load.error;
  EXPECT_EQ(load.error.find('\n'), std::string::npos) << load.error;
}

const std::string kSofa =
    "obstacles:\n  - name: sofa\n    polygon: [[1, 1], [2, 1], [2, 2], [1, 2]]\n    surface: soft\n";

INSTANTIATE_TEST_SUITE_P(
    Table, WorldFileBad,
    ::testing::Values(
        BadWorld{"notAMapping", "- a\n- b\n", "not an nxtmap world file: not a YAML mapping"},
        BadWorld{"empty", "", "not a YAML mapping"},
        BadWorld{"rosMap", "image: m.pgm\nresolution: 0.1\n", "it has 'image:', so it is a ROS map_server map"},
        BadWorld{"noMarker", "name: x\noutline: {polygon: [[0, 0], [1, 0], [0, 1]]}\n", "no 'nxtmap_world: 1' key"},
        BadWorld{"version2", "nxtmap_world: 2\n", "w.yaml:1: 'nxtmap_world' must be 1"},
        BadWorld{"yamlSyntax", "nxtmap_world: 1\noutline: [[0, 0]\n", "w.yaml: yaml-cpp: error at line"},
        BadWorld{"topLevelTypo", room("obstacle: []\n"),
                 "w.yaml:4: unknown key 'obstacle' in the top level (known: nxtmap_world, name, outline, "
                 "obstacles, start, transform)"},
        BadWorld{"keyTwice", room("name: a\nname: b\n"), "w.yaml:5: key 'name' given twice in the top level"},
        BadWorld{"nameTwoLines", room("name: \"a\\nb\"\n"), "'name' must be one line of text"},
        BadWorld{"nameTooLong", room("name: " + std::string(101, 'x') + "\n"), "'name' must be a text of 1 to 100"},
        BadWorld{"missingOutline", "nxtmap_world: 1\n", "w.yaml: missing 'outline'"},
        BadWorld{"outlineAList", "nxtmap_world: 1\noutline: [[0, 0], [1, 0], [0, 1]]\n", "'outline' must be a mapping"},
        BadWorld{"outlineNoPolygon", "nxtmap_world: 1\noutline: {surface: hard}\n", "outline: missing 'polygon'"},
        BadWorld{"openOutline", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0]]}\n",
                 "w.yaml:2: outline: polygon is open or degenerate: it needs at least 3 distinct points, has 2"},
        BadWorld{"repeatedPoints", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [4, 0], [0, 0]]}\n",
                 "at least 3 distinct points, has 2"},
        BadWorld{"onOneLine", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [2, 0], [4, 0]]}\n",
                 "outline: polygon has no area (its points lie on one line)"},
        BadWorld{"bowTie", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [0, 3], [4, 3]]}\n",
                 "outline: polygon crosses itself: side polygon[1]-polygon[2] meets side polygon[3]-polygon[0]"},
        BadWorld{"tinyTriangle", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [0.0005, 0], [0, 0.0005]]}\n",
                 "outline: polygon has almost no area"},
        BadWorld{"foldsBack", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [4, 3], [4, 1]]}\n",
                 "polygon crosses itself: side polygon[1]-polygon[2] meets side polygon[2]-polygon[3]"},
        BadWorld{"vertexOnASide", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [4, 3], [2, 0], [0, 3]]}\n",
                 "polygon crosses itself"},
        BadWorld{"sofaCrossesItself",
                 room("obstacles:\n  - name: sofa\n    polygon: [[1, 1], [2, 2], [2, 1], [1, 2]]\n"),
                 "w.yaml:6: obstacles[0] (sofa): polygon crosses itself"},
        BadWorld{"nanCoordinate", "nxtmap_world: 1\noutline: {polygon: [[0, .nan], [4, 0], [0, 3]]}\n",
                 "outline polygon[0] y must be a finite number within +-1000, not '.nan'"},
        BadWorld{"infCoordinate", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [.inf, 0], [0, 3]]}\n",
                 "outline polygon[1] x must be a finite number"},
        BadWorld{"farCoordinate", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [1001, 0], [0, 3]]}\n",
                 "within +-1000, not '1001'"},
        BadWorld{"wordCoordinate", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [four, 0], [0, 3]]}\n", "not 'four'"},
        BadWorld{"threeNumbers", "nxtmap_world: 1\noutline: {polygon: [[0, 0, 0], [4, 0], [0, 3]]}\n",
                 "outline polygon[0] must be a point [x, y] in metres"},
        BadWorld{"tooWide", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [300, 0], [300, 3], [0, 3]]}\n",
                 "outline: the outline spans 300 x 3 m; a world is at most 200 m a side"},
        BadWorld{"obstaclesNotAList", room("obstacles: {polygon: []}\n"), "'obstacles' must be a list"},
        BadWorld{"obstacleKeyTypo", room("obstacles:\n  - polygon: [[1, 1], [2, 1], [2, 2]]\n    surfce: soft\n"),
                 "w.yaml:6: unknown key 'surfce' in obstacles[0] (known: name, polygon, circle, radius, wall, "
                 "surface)"},
        BadWorld{"twoKinds", room("obstacles:\n  - {polygon: [[1, 1], [2, 1], [2, 2]], circle: [1, 1]}\n"),
                 "obstacles[0]: needs exactly one of 'polygon', 'circle', 'wall'"},
        BadWorld{"noKind", room("obstacles:\n  - {name: ghost}\n"), "obstacles[0] (ghost): needs exactly one of"},
        BadWorld{"unknownSurface", room("obstacles:\n  - polygon: [[1, 1], [2, 1], [2, 2]]\n    surface: velvet\n"),
                 "w.yaml:6: obstacles[0]: unknown surface 'velvet' (known: hard, soft, thin)"},
        BadWorld{"outlineSurface", "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [0, 3]], surface: glass}\n",
                 "unknown surface 'glass'"},
        BadWorld{"radiusZero", room("obstacles:\n  - {circle: [1, 1], radius: 0}\n"),
                 "obstacles[0]: circle radius must be > 0 and at most 5 m, not 0"},
        BadWorld{"radiusNegative", room("obstacles:\n  - {circle: [1, 1], radius: -0.01}\n"),
                 "circle radius must be > 0"},
        BadWorld{"radiusHuge", room("obstacles:\n  - {circle: [1, 1], radius: 6}\n"), "at most 5 m, not 6"},
        BadWorld{"radiusMissing", room("obstacles:\n  - {circle: [1, 1]}\n"), "circle needs a 'radius'"},
        BadWorld{"radiusOnAPolygon", room("obstacles:\n  - {polygon: [[1, 1], [2, 1], [2, 2]], radius: 1}\n"),
                 "'radius' belongs to a circle"},
        BadWorld{"wallOfOnePoint", room("obstacles:\n  - {wall: [[1, 1], [1, 1]]}\n"),
                 "obstacles[0]: wall needs at least 2 distinct points, has 1"},
        BadWorld{"sofaOutside", room("obstacles:\n  - name: sofa\n    polygon: [[3, 1], [5, 1], [5, 2], [3, 2]]\n"),
                 "obstacles[0] (sofa): polygon[1] (5, 1) m lies outside the outline"},
        BadWorld{"sofaAcrossANotch",
                 "nxtmap_world: 1\noutline: {polygon: [[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]]}\n"
                 "obstacles:\n  - polygon: [[1, 3], [3, 1], [3.5, 1.5], [1.5, 3.5]]\n",
                 "obstacles[0]: side polygon[2]-polygon[3] crosses the outline"},
        BadWorld{"legOutside", room("obstacles:\n  - {circle: [5, 1], radius: 0.01}\n"),
                 "obstacles[0]: circle centre (5, 1) m lies outside the outline"},
        BadWorld{"curtainOutside", room("obstacles:\n  - {wall: [[1, 1], [1, 4]]}\n"),
                 "obstacles[0]: wall[1] (1, 4) m lies outside the outline"},
        BadWorld{"overlappingFurniture",
                 room(kSofa + "  - name: chair\n    polygon: [[1.5, 1.5], [2.5, 1.5], [2.5, 2.5], [1.5, 2.5]]\n"),
                 "obstacles[1] (chair): polygon overlaps obstacles[0] (sofa)"},
        BadWorld{"furnitureInFurniture",
                 room(kSofa + "  - name: cushion\n    polygon: [[1.2, 1.2], [1.8, 1.2], [1.8, 1.8]]\n"),
                 "obstacles[1] (cushion): polygon overlaps obstacles[0] (sofa)"},
        BadWorld{"sameFurnitureTwice", room(kSofa + "  - polygon: [[2, 2], [1, 2], [1, 1], [2, 1]]\n"),
                 "obstacles[1]: polygon overlaps obstacles[0] (sofa)"},
        BadWorld{"startOutside", room("start: {x: 5, y: 1, yaw: 0}\n"),
                 "w.yaml:4: start: (5, 1) m lies outside the outline"},
        BadWorld{"startOnTheOutline", room("start: {x: 0, y: 1, yaw: 0}\n"), "start: (0, 1) m lies on the outline"},
        BadWorld{"startInTheSofa", room(kSofa + "start: {x: 1.5, y: 1.5, yaw: 0}\n"),
                 "start: (1.5, 1.5) m lies inside or on obstacles[0] (sofa)"},
        BadWorld{"startInALeg",
                 room("obstacles:\n  - {name: leg, circle: [1, 1], radius: 0.02}\n"
                      "start: {x: 1.01, y: 1, yaw: 0}\n"),
                 "lies inside or on obstacles[0] (leg)"},
        BadWorld{"startOnTheCurtain",
                 room("obstacles:\n  - {name: curtain, wall: [[1, 1], [3, 1]], surface: soft}\n"
                      "start: {x: 2, y: 1, yaw: 0}\n"),
                 "lies inside or on obstacles[0] (curtain)"},
        BadWorld{"startLeftInTheSofaByTheTransform",
                 room(kSofa + "start: {x: 1.5, y: 2.5, yaw: 0}\ntransform: {offset: [0, 1]}\n"),
                 "start: (1.5, 2.5) m lies inside or on obstacles[0] (sofa)"},
        BadWorld{"startWithoutYaw", room("start: {x: 1, y: 1}\n"), "start: must be {x: metres, y: metres, yaw:"},
        BadWorld{"startKeyTypo", room("start: {x: 1, y: 1, yaw: 0, z: 0}\n"), "unknown key 'z' in start"},
        BadWorld{"yawTooLarge", room("start: {x: 1, y: 1, yaw: 400}\n"),
                 "start yaw must be a finite number within +-360"},
        BadWorld{"transformTypo", room("transform: {rotate: 10}\n"),
                 "unknown key 'rotate' in transform (known: rotate_deg, offset)"},
        BadWorld{"offsetNotAPoint", room("transform: {offset: 0.1}\n"), "offset must be a point [x, y] in metres"},
        BadWorld{"tooManyPoints",
                 [] {
                   std::string pts;
                   for (int i = 0; i < 1001; ++i) pts += (i ? ", [" : "[") + std::to_string(i % 3) + ", 0]";
                   return "nxtmap_world: 1\noutline: {polygon: [" + pts + "]}\n";
                 }(),
                 "outline polygon has 1001 points; at most 1000"},
        BadWorld{"tooManyPointsInAll",
                 [] {
                   // One list of 7 points named 1500 times through a YAML alias: 10500 points.
                   std::string walls =
                       "obstacles:\n  - wall: &w [[1, 1], [2, 1], [2, 2], [1, 2], [1, 1.5], "
                       "[1.5, 1.5], [1.5, 1.2]]\n";
                   for (int i = 0; i < 1499; ++i) walls += "  - wall: *w\n";
                   return room(walls);
                 }(),
                 "the world has more than 10000 points in all"},
        BadWorld{"tooManyObstacles",
                 [] {
                   std::string legs = "obstacles:\n";
                   for (int i = 0; i < 2001; ++i) legs += "  - {circle: [1, 1], radius: 0.01}\n";
                   return room(legs);
                 }(),
                 "w.yaml:5: 'obstacles' has 2001 entries; at most 2000"}),
    [](const ::testing::TestParamInfo<BadWorld>& p) { return std::string(p.param.label); });

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
