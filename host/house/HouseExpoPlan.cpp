#include "host/house/HouseExpoPlan.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <sstream>

#include "host/sim/InputFile.hpp"

namespace nxtmap::house {
namespace {

struct Point {
  double x, y;
};

// The outline's bounding box, metres.
struct Extent {
  double minX, minY, maxX, maxY;
};

HousePlanLoad fail(const std::string& name, const std::string& what) {
  HousePlanLoad r;
  r.error = name + ": " + what;
  return r;
}

std::string metres(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

bool planCoordinate(const nlohmann::json& v) {
  if (!v.is_number()) return false;
  const double d = v.get<double>();
  return std::isfinite(d) && std::fabs(d) <= kMaxPlanCoordM;
}

bool readPoint(const nlohmann::json& j, Point& p) {
  if (!j.is_array() || j.size() != 2 || !planCoordinate(j[0]) || !planCoordinate(j[1])) return false;
  p.x = j[0].get<double>();
  p.y = j[1].get<double>();
  return true;
}

// The outline polygon from `verts`; an error message, or "" when it is good.
std::string readOutline(const nlohmann::json& j, std::vector<Point>& poly) {
  if (!j.contains("verts") || !j["verts"].is_array() || j["verts"].size() < 3) {
    return "'verts' must be an array of at least 3 [x, y] points";
  }
  const nlohmann::json& verts = j["verts"];
  if (verts.size() > kMaxPlanPoints) {
    return "'verts' holds " + std::to_string(verts.size()) + " points, more than " + std::to_string(kMaxPlanPoints);
  }
  for (const auto& v : verts) {
    Point p{};
    if (!readPoint(v, p)) {
      return "'verts' holds an entry that is not an [x, y] pair of numbers within -" + metres(kMaxPlanCoordM) + ".." +
             metres(kMaxPlanCoordM) + " m";
    }
    poly.push_back(p);
  }
  return "";
}

Extent extentOf(const std::vector<Point>& poly) {
  Extent e{poly[0].x, poly[0].y, poly[0].x, poly[0].y};
  for (const Point& p : poly) {
    e.minX = std::min(e.minX, p.x);
    e.maxX = std::max(e.maxX, p.x);
    e.minY = std::min(e.minY, p.y);
    e.maxY = std::max(e.maxY, p.y);
  }
  return e;
}

// Rows of '.' (cell centre inside the outline, even-odd rule) and '#', row 0 at the top; x0, y0 the
// lower-left corner in metres. Each row: the outline's crossings of the row's centre line, sorted, then
// one walk along the row (a centre is inside when an odd number of crossings lie to its right).
std::vector<std::string> rasterise(const std::vector<Point>& poly, double x0, double y0, int w, int h, double res,
                                   int& freeCells) {
  std::vector<std::string> rows(static_cast<size_t>(h), std::string(static_cast<size_t>(w), '#'));
  std::vector<double> crossings;
  freeCells = 0;
  for (int row = 0; row < h; ++row) {
    const double cy = y0 + (h - row - 0.5) * res;
    crossings.clear();
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
      const Point& a = poly[i];
      const Point& b = poly[j];
      if ((a.y > cy) != (b.y > cy)) crossings.push_back(a.x + (cy - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    std::sort(crossings.begin(), crossings.end());
    size_t left = 0;  // crossings at or left of the cell's centre
    for (int col = 0; col < w; ++col) {
      const double cx = x0 + (col + 0.5) * res;
      while (left < crossings.size() && crossings[left] <= cx) ++left;
      if ((crossings.size() - left) % 2 == 1) {
        rows[static_cast<size_t>(row)][static_cast<size_t>(col)] = '.';
        ++freeCells;
      }
    }
  }
  return rows;
}

// The outline as one Hard ring in the raster's plane (cm, y down from the top edge at y0 + h * res).
std::shared_ptr<const sim::Scene> outlineScene(const std::vector<Point>& poly, double x0, double y0, int h,
                                               double res) {
  const double topM = y0 + h * res;
  sim::Ring ring;
  ring.surface = sim::Surface::Hard;
  for (const Point& p : poly) ring.points.emplace_back((p.x - x0) * 100.0, (topM - p.y) * 100.0);
  auto scene = std::make_shared<sim::Scene>();
  scene->addRing(std::move(ring));
  scene->finish();
  return scene;
}

// A room category ("Living_Room"): 1..48 of [A-Za-z0-9_-], not "null" in any case, so that the label named
// after it (lower case, "room_" before a leading digit, "_N" after a repeat) is a valid label name.
bool validCategory(const std::string& c) {
  std::string lower;
  for (const char ch : c) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return !c.empty() && c.size() <= 48 && lower != "null" && std::all_of(c.begin(), c.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
  });
}

// The room boxes of `room_category` into world cells; an error message, or "" when they are good.
std::string readRooms(const nlohmann::json& j, const Extent& outline, double x0, double y0, int w, int h, double res,
                      std::vector<PlanRoom>& rooms) {
  if (!j.contains("room_category")) return "";
  if (!j["room_category"].is_object()) return "'room_category' must be an object";
  const auto toCol = [&](double x) { return static_cast<int>(std::floor((x - x0) / res)); };
  const auto toRow = [&](double y) { return h - 1 - static_cast<int>(std::floor((y - y0) / res)); };
  for (const auto& [category, boxes] : j["room_category"].items()) {
    if (!validCategory(category)) {
      return "room_category names must be 1..48 of A-Z a-z 0-9 _ - (not 'null'; they become label names)";
    }
    if (!boxes.is_array()) return "room_category '" + category + "' must be a list of boxes";
    for (const auto& b : boxes) {
      if (!b.is_array() || b.size() != 4 || !std::all_of(b.begin(), b.end(), planCoordinate)) {
        return "room_category '" + category + "' holds a box that is not [x1, y1, x2, y2] of numbers within -" +
               metres(kMaxPlanCoordM) + ".." + metres(kMaxPlanCoordM) + " m";
      }
      if (rooms.size() == kMaxPlanRoomBoxes) {
        return "'room_category' holds more than " + std::to_string(kMaxPlanRoomBoxes) + " boxes";
      }
      const double bx1 = b[0].get<double>(), by1 = b[1].get<double>(), bx2 = b[2].get<double>(),
                   by2 = b[3].get<double>();
      if (std::max(bx1, bx2) < outline.minX || std::min(bx1, bx2) > outline.maxX || std::max(by1, by2) < outline.minY ||
          std::min(by1, by2) > outline.maxY) {
        return "room_category '" + category + "' holds a box [" + metres(bx1) + ", " + metres(by1) + ", " +
               metres(bx2) + ", " + metres(by2) + "] that lies outside the outline";
      }
      PlanRoom r;
      r.category = category;
      r.minCol = std::clamp(toCol(std::min(bx1, bx2)), 0, w - 1);
      r.maxCol = std::clamp(toCol(std::max(bx1, bx2)), 0, w - 1);
      r.minRow = std::clamp(toRow(std::max(by1, by2)), 0, h - 1);
      r.maxRow = std::clamp(toRow(std::min(by1, by2)), 0, h - 1);
      r.minXCm = (std::min(bx1, bx2) - x0) * 100.0;
      r.maxXCm = (std::max(bx1, bx2) - x0) * 100.0;
      r.minYCm = (y0 + h * res - std::max(by1, by2)) * 100.0;
      r.maxYCm = (y0 + h * res - std::min(by1, by2)) * 100.0;
      rooms.push_back(r);
    }
  }
  return "";
}

// `id` when present: 1..128 printable ASCII characters (it is printed).
bool validId(const std::string& id) {
  return !id.empty() && id.size() <= 128 &&
         std::all_of(id.begin(), id.end(), [](char c) { return c >= 0x20 && c <= 0x7e; });
}

}  // namespace

HousePlanLoad parseHouseExpo(const std::string& text, const std::string& name, double res) {
  if (!(res >= 0.01 && res <= 1.0)) return fail(name, "resolution must be 0.01 .. 1 m");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // a syntax error, or a number beyond a double's range
    return fail(name, std::string("not valid JSON (") + e.what() + ")");
  }
  if (!j.is_object()) return fail(name, "not a HouseExpo plan (expected a JSON object)");
  std::vector<Point> poly;
  const std::string outlineError = readOutline(j, poly);
  if (!outlineError.empty()) return fail(name, outlineError);
  const Extent e = extentOf(poly);
  if (e.maxX - e.minX > kMaxPlanSideM || e.maxY - e.minY > kMaxPlanSideM) {
    return fail(name, "the plan is " + metres(e.maxX - e.minX) + " x " + metres(e.maxY - e.minY) + " m, larger than " +
                          metres(kMaxPlanSideM) + " m a side");
  }
  const double x0 = std::floor(e.minX / res) * res - res;  // one wall ring around the outline
  const double y0 = std::floor(e.minY / res) * res - res;
  const double widthCells = std::ceil((e.maxX - x0) / res) + 1.0;
  const double heightCells = std::ceil((e.maxY - y0) / res) + 1.0;
  if (widthCells > sim::World::kMaxSide || heightCells > sim::World::kMaxSide) {
    return fail(name, "the plan is larger than " + std::to_string(sim::World::kMaxSide) + " cells a side");
  }
  const int w = static_cast<int>(widthCells), h = static_cast<int>(heightCells);
  int freeCells = 0;
  std::vector<std::string> rows = rasterise(poly, x0, y0, w, h, res, freeCells);
  if (freeCells == 0) return fail(name, "the outline encloses no cell");

  HousePlan plan{"", 0, {}, sim::World::fromRows(rows, res), x0, y0, outlineScene(poly, x0, y0, h, res)};
  const std::string roomsError = readRooms(j, e, x0, y0, w, h, res, plan.rooms);
  if (!roomsError.empty()) return fail(name, roomsError);
  plan.id = name;
  if (j.contains("id")) {
    if (!j["id"].is_string() || !validId(j["id"].get<std::string>())) {
      return fail(name, "'id' must be a string of 1..128 printable characters");
    }
    plan.id = j["id"].get<std::string>();
  }
  plan.roomNum = static_cast<int>(plan.rooms.size());
  if (j.contains("room_num")) {
    const nlohmann::json& n = j["room_num"];
    if (!n.is_number_integer() || n.get<long long>() < 0 ||
        n.get<long long>() > static_cast<long long>(kMaxPlanRoomBoxes)) {
      return fail(name, "'room_num' must be a whole number in 0.." + std::to_string(kMaxPlanRoomBoxes));
    }
    plan.roomNum = n.get<int>();
  }
  HousePlanLoad out;
  out.plan = std::move(plan);
  return out;
}

HousePlanLoad loadHouseExpo(const std::string& path, double resolutionM) {
  HousePlanLoad refused;
  const std::optional<std::string> text = sim::readInputFile(path, kMaxPlanFileBytes, "HouseExpo plan", refused.error);
  if (!text) return refused;
  return parseHouseExpo(*text, path, resolutionM);
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
