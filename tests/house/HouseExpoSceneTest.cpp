#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "host/house/HouseExpoPlan.hpp"
#include "host/sim/RayCast.hpp"
#include "host/sim/SceneGeometry.hpp"

namespace nxtmap::house {
namespace {

const std::string kDir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/houseexpo/";
const char* const kPlans[] = {"1f99717550c31ae321ca2313edceedcc.json", "3a977bda0c177c31c8c64e8076562d5a.json",
                              "75555d2f4a69546c4c811f85bac572d9.json", "house_expo_room_0000.json",
                              "house_expo_room_1451.json"};

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

double nearestSideCm(const sim::Scene& scene, const sim::Vec2& p) {
  double near = std::numeric_limits<double>::infinity();
  for (const sim::Edge& e : scene.edges()) near = std::min(near, sim::geometry::pointSegmentDistance(p, e.a, e.b));
  return near;
}

// The outline is kept point for point (no snapping) in the raster's plane.
TEST(HouseExpoScene, KeepsTheOutlineExactlyInTheRastersPlane) {
  for (const char* file : kPlans) {
    const HousePlanLoad l = loadHouseExpo(kDir + file, 0.10);
    ASSERT_TRUE(l.plan) << l.error;
    const HousePlan& p = *l.plan;
    ASSERT_TRUE(p.scene) << file;
    ASSERT_EQ(p.scene->rings().size(), 1u) << file;
    const sim::Ring& ring = p.scene->rings()[0];
    EXPECT_EQ(ring.surface, sim::Surface::Hard);
    const nlohmann::json verts = readJson(kDir + file)["verts"];
    ASSERT_EQ(ring.points.size(), verts.size()) << file;
    const double topM = p.originYM + p.world.height() * p.world.resolutionM();
    for (size_t i = 0; i < verts.size(); ++i) {
      EXPECT_NEAR(ring.points[i].x(), (verts[i][0].get<double>() - p.originXM) * 100.0, 1e-9) << file << " " << i;
      EXPECT_NEAR(ring.points[i].y(), (topM - verts[i][1].get<double>()) * 100.0, 1e-9) << file << " " << i;
    }
  }
}

// The raster frees a cell whose centre lies inside the outline: at every centre not within 0.1 mm of the
// outline the scene agrees. Axis rays from free centres meet the outline no later than half a cell past
// the raster's face (the blocked centre beyond it lies outside the outline).
TEST(HouseExpoScene, AgreesWithTheRasterAtCellCentres) {
  for (const char* file : kPlans) {
    for (const double res : {0.10, 0.05}) {
      const HousePlanLoad l = loadHouseExpo(kDir + file, res);
      ASSERT_TRUE(l.plan) << l.error;
      const sim::World& w = l.plan->world;
      const sim::Scene& scene = *l.plan->scene;
      const double cell = res * 100.0;
      int differ = 0;
      for (int row = 0; row < w.height(); ++row) {
        for (int col = 0; col < w.width(); ++col) {
          const sim::Vec2 centre((col + 0.5) * cell, (row + 0.5) * cell);
          if (scene.solidAt(centre) != w.blocked(col, row)) {  // only on the outline, where rounding decides
            ASSERT_LT(nearestSideCm(scene, centre), 0.01) << file << " cell " << col << ", " << row;
            ++differ;
            continue;
          }
          if (w.blocked(col, row) || (col + row) % 3 != 0) continue;
          for (const double deg : {0.0, 90.0, 180.0, 270.0}) {
            const sim::RayHit raster = sim::castRay(w, cell, centre.x(), centre.y(), deg, 1e5);
            const sim::SceneHit exact = scene.cast(centre, deg, 1e5);
            ASSERT_TRUE(raster.hit && exact.hit) << file;
            EXPECT_LE(exact.distanceCm, raster.distanceCm + cell / 2 + 1e-6) << file << " " << col << ", " << row;
          }
        }
      }
      EXPECT_LT(differ, w.width()) << file;
    }
  }
}

TEST(HouseExpoScene, TheInteriorWallAndItsDoorwayLieWhereThePlanPutsThem) {
  const HousePlanLoad l = loadHouseExpo(kDir + "1f99717550c31ae321ca2313edceedcc.json", 0.10);
  ASSERT_TRUE(l.plan) << l.error;
  const HousePlan& p = *l.plan;
  const double topM = p.originYM + p.world.height() * 0.10;
  const auto plane = [&](double xM, double yM) { return sim::Vec2((xM - p.originXM) * 100, (topM - yM) * 100); };
  // The wall x 2.88 .. 3.0 m below y 1.13 m; its doorway spans y 1.13 .. 2.35 m; the east wall at 6.4 m.
  EXPECT_NEAR(p.scene->cast(plane(2.75, 0.5), 90, 500).distanceCm, 13.0, 1e-9);
  EXPECT_NEAR(p.scene->cast(plane(2.75, 1.7), 90, 500).distanceCm, 365.0, 1e-9);
  EXPECT_TRUE(p.scene->solidAt(plane(2.95, 0.5)));
  EXPECT_FALSE(p.scene->solidAt(plane(2.95, 1.7)));
}

}  // namespace
}  // namespace nxtmap::house
