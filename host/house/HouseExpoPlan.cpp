#include "host/house/HouseExpoPlan.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <sstream>

namespace nxtmap::house {
namespace {

struct Point {
  double x, y;
};

HousePlanLoad fail(const std::string& name, const std::string& what) {
  HousePlanLoad r;
  r.error = name + ": " + what;
  return r;
}

bool readPoint(const nlohmann::json& j, Point& p) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) return false;
  p.x = j[0].get<double>();
  p.y = j[1].get<double>();
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// Even-odd rule: does a horizontal ray from (x, y) to +x cross the outline an odd number of times?
bool inside(const std::vector<Point>& poly, double x, double y) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Point& a = poly[i];
    const Point& b = poly[j];
    if ((a.y > y) != (b.y > y)) {
      const double xc = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x < xc) in = !in;
    }
  }
  return in;
}

}  // namespace

HousePlanLoad parseHouseExpo(const std::string& text, const std::string& name, double res) {
  if (!(res >= 0.01 && res <= 1.0)) return fail(name, "resolution must be 0.01 .. 1 m");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    return fail(name, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object()) return fail(name, "not a HouseExpo plan (expected a JSON object)");
  if (!j.contains("verts") || !j["verts"].is_array() || j["verts"].size() < 3) {
    return fail(name, "'verts' must be an array of at least 3 [x, y] points");
  }
  std::vector<Point> poly;
  for (const auto& v : j["verts"]) {
    Point p{};
    if (!readPoint(v, p)) return fail(name, "'verts' holds an entry that is not an [x, y] pair of numbers");
    poly.push_back(p);
  }
  double minX = poly[0].x, maxX = poly[0].x, minY = poly[0].y, maxY = poly[0].y;
  for (const Point& p : poly) {
    minX = std::min(minX, p.x);
    maxX = std::max(maxX, p.x);
    minY = std::min(minY, p.y);
    maxY = std::max(maxY, p.y);
  }
  const double x0 = std::floor(minX / res) * res - res;  // one wall ring around the outline
  const double y0 = std::floor(minY / res) * res - res;
  const double widthCells = std::ceil((maxX - x0) / res) + 1.0;
  const double heightCells = std::ceil((maxY - y0) / res) + 1.0;
  if (widthCells > sim::World::kMaxSide || heightCells > sim::World::kMaxSide) {
    return fail(name, "the plan is larger than " + std::to_string(sim::World::kMaxSide) + " cells a side");
  }
  const int w = static_cast<int>(widthCells), h = static_cast<int>(heightCells);
  std::vector<std::string> rows(static_cast<size_t>(h), std::string(static_cast<size_t>(w), '#'));
  int freeCells = 0;
  for (int row = 0; row < h; ++row) {
    const double cy = y0 + (h - row - 0.5) * res;
    for (int col = 0; col < w; ++col) {
      const double cx = x0 + (col + 0.5) * res;
      if (inside(poly, cx, cy)) {
        rows[static_cast<size_t>(row)][static_cast<size_t>(col)] = '.';
        ++freeCells;
      }
    }
  }
  if (freeCells == 0) return fail(name, "the outline encloses no cell");

  HousePlan plan{"", 0, {}, sim::World::fromRows(rows, res), x0, y0};
  plan.id = j.contains("id") && j["id"].is_string() ? j["id"].get<std::string>() : name;
  const auto toCol = [&](double x) { return static_cast<int>(std::floor((x - x0) / res)); };
  const auto toRow = [&](double y) { return h - 1 - static_cast<int>(std::floor((y - y0) / res)); };
  if (j.contains("room_category")) {
    if (!j["room_category"].is_object()) return fail(name, "'room_category' must be an object");
    for (const auto& [category, boxes] : j["room_category"].items()) {
      if (!boxes.is_array()) return fail(name, "room_category '" + category + "' must be a list of boxes");
      for (const auto& b : boxes) {
        if (!b.is_array() || b.size() != 4 || !std::all_of(b.begin(), b.end(), [](const auto& v) { return v.is_number(); })) {
          return fail(name, "room_category '" + category + "' holds a box that is not [x1, y1, x2, y2]");
        }
        PlanRoom r;
        r.category = category;
        const double bx1 = b[0].get<double>(), by1 = b[1].get<double>(), bx2 = b[2].get<double>(), by2 = b[3].get<double>();
        r.minCol = std::clamp(toCol(std::min(bx1, bx2)), 0, w - 1);
        r.maxCol = std::clamp(toCol(std::max(bx1, bx2)), 0, w - 1);
        r.minRow = std::clamp(toRow(std::max(by1, by2)), 0, h - 1);
        r.maxRow = std::clamp(toRow(std::min(by1, by2)), 0, h - 1);
        plan.rooms.push_back(r);
      }
    }
  }
  plan.roomNum = j.contains("room_num") && j["room_num"].is_number_integer() ? j["room_num"].get<int>()
                                                                              : static_cast<int>(plan.rooms.size());
  HousePlanLoad out;
  out.plan = std::move(plan);
  return out;
}

HousePlanLoad loadHouseExpo(const std::string& path, double resolutionM) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(path, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  HousePlanLoad r = parseHouseExpo(text.str(), path, resolutionM);
  return r;
}

bool defaultStart(const HousePlan& plan, int& col, int& row) {
  const sim::World& w = plan.world;
  // Distance to the nearest wall (4-connected steps), by a multi-source flood from every wall.
  std::vector<int> dist(static_cast<size_t>(w.width() * w.height()), -1);
  std::deque<int> queue;
  for (int r = 0; r < w.height(); ++r) {
    for (int c = 0; c < w.width(); ++c) {
      if (w.blocked(c, r)) {
        dist[static_cast<size_t>(r * w.width() + c)] = 0;
        queue.push_back(r * w.width() + c);
      }
    }
  }
  static const int kDc[4] = {1, -1, 0, 0}, kDr[4] = {0, 0, 1, -1};
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const int c = i % w.width(), r = i / w.width();
    for (int d = 0; d < 4; ++d) {
      const int nc = c + kDc[d], nr = r + kDr[d];
      if (!w.inside(nc, nr) || dist[static_cast<size_t>(nr * w.width() + nc)] >= 0) continue;
      dist[static_cast<size_t>(nr * w.width() + nc)] = dist[static_cast<size_t>(i)] + 1;
      queue.push_back(nr * w.width() + nc);
    }
  }
  double cc = w.width() / 2.0, cr = w.height() / 2.0;
  if (!plan.rooms.empty()) {
    cc = (plan.rooms[0].minCol + plan.rooms[0].maxCol) / 2.0;
    cr = (plan.rooms[0].minRow + plan.rooms[0].maxRow) / 2.0;
  }
  int best = -1;
  double bestNear = 0.0;
  for (int r = 0; r < w.height(); ++r) {
    for (int c = 0; c < w.width(); ++c) {
      const int d = dist[static_cast<size_t>(r * w.width() + c)];
      if (d <= 0) continue;
      const int capped = std::min(d, 4);  // far enough from walls; then prefer the room's centre
      const double near = std::hypot(c - cc, r - cr);
      const int bestCapped = best < 0 ? -1 : std::min(dist[static_cast<size_t>(best)], 4);
      if (best < 0 || capped > bestCapped || (capped == bestCapped && near < bestNear)) {
        best = r * w.width() + c;
        bestNear = near;
      }
    }
  }
  if (best < 0) return false;
  col = best % w.width();
  row = best / w.width();
  return true;
}

}  // namespace nxtmap::house
