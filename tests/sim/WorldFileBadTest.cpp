// WorldFile's bad documents: each refused with one line naming the file, the element and the problem.
#include "host/sim/WorldFile.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tests/sim/RoomText.hpp"

namespace nxtmap::sim {
namespace {

using test::room;

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

}  // namespace
}  // namespace nxtmap::sim
