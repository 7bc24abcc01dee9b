// Spoiled houses and HouseExpo plans (defects 2, 6, 7 and 8 of issue 15): far origins and transforms, labels
// and gateway cells outside their rooms, rooms placed far apart, devices in place of room maps, and plans
// with absurd numbers or sizes. Each is refused by every command that loads it.
#include <string>
#include <vector>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/Fixtures.hpp"

namespace nxtmap::adversarial {
namespace {

struct BadHouse {
  std::string name;
  std::function<void(const CaseDirs&)> setup;
};

// room1's origin line in the fixture, as sim-house wrote it.
const char* kRoom1Origin = "origin: [-3.3000000000000003, -0.9, 0]";

std::vector<BadHouse> badHouses() {
  return {
      {"roomOriginFar", houseWith("room1.yaml", kRoom1Origin, "origin: [4000, 0, 0]")},
      {"roomOriginFarInRange", houseWith("room1.yaml", kRoom1Origin, "origin: [400, -0.9, 0]")},
      {"roomOriginFarNegative", houseWith("room1.yaml", kRoom1Origin, "origin: [-99999, -0.9, 0]")},
      {"roomOriginNan", houseWith("room1.yaml", kRoom1Origin, "origin: [.nan, -0.9, 0]")},
      {"roomResolutionTiny", houseWith("room1.yaml", "resolution: 0.1", "resolution: 1e-300")},
      {"toHouseIntMax", houseWith("house.yaml", "{x: -2, y: -9", "{x: 2147483647, y: -9")},
      {"toHouseFar", houseWith("house.yaml", "{x: 20, y: -7", "{x: 20, y: -7000000")},
      {"toHouseQuarterTurns", houseWith("house.yaml", "quarter_turns_clockwise: 2", "quarter_turns_clockwise: 7")},
      {"labelFar", houseWith("house.yaml", "chair: [2, 3]", "chair: [70000, 1]")},
      {"labelText", houseWith("house.yaml", "chair: [2, 3]", "chair: [left, up]")},
      {"labelEscapeName", houseWith("house.yaml", "chair: [2, 3]", "\"\\e[2Jchair\": [2, 3]")},
      {"gatewayCellFar", houseWith("house.yaml", "cells_a: [[-3, -8]", "cells_a: [[-3, -80000]")},
      {"gatewayUnknownRoom", houseWith("house.yaml", "rooms: [room0, room1]", "rooms: [room0, attic]")},
      {"gatewayCountsDiffer", houseWith("house.yaml", "cells_b: [[1, -1], ", "cells_b: [")},
      {"resolutionMismatch", houseWith("house.yaml", "resolution: 0.1", "resolution: 0.2")},
      {"formatUnknown", houseWith("house.yaml", "nxtmap-house-1", "nxtmap-house-9")},
      {"roomMapDevZero",
       [](const CaseDirs& d) {
         houseWith()(d);
         ::unlink(d.path("house/room1.pgm").c_str());
         symlinkTo(d, "/dev/zero", "house/room1.pgm");
       }},
      {"houseYamlDevZero",
       [](const CaseDirs& d) {
         houseWith()(d);
         ::unlink(d.path("house/house.yaml").c_str());
         symlinkTo(d, "/dev/zero", "house/house.yaml");
       }},
      {"roomMapFolder", houseWith("house.yaml", "map: room1.yaml", "map: .")},
      {"roomMapOutside", houseWith("house.yaml", "map: room1.yaml", "map: /etc/passwd")},
      {"houseYamlMissing", [](const CaseDirs& d) { d.write("house/readme", "not a house"); }},
      {"notAFolder", [](const CaseDirs& d) { d.write("house", "a file"); }},
  };
}

// A HouseExpo plan: one room, a rectangle, its numbers given as text.
std::string plan(const std::string& verts, const std::string& bboxMax = "[4.0, 3.0]") {
  return "{\"id\": \"adv\", \"room_num\": 1, \"room_category\": {\"living\": [[0.0, 0.0, " + bboxMax.substr(1) +
         "]}, \"verts\": " + verts + ", \"bbox\": {\"min\": [0.0, 0.0], \"max\": " + bboxMax + "}}";
}

std::string manyPoints(int n) {
  std::string v = "[";
  for (int i = 0; i < n; ++i) {  // a fine zig-zag along the bottom, then the other three corners
    v += "[" + std::to_string(4.0 * i / n) + ", " + (i % 2 == 0 ? "0.0" : "0.01") + "], ";
  }
  return v + "[4.0, 0.0], [4.0, 3.0], [0.0, 3.0]]";
}

std::vector<BadHouse> badPlans() {
  const auto planFile = [](std::string text) { return [text](const CaseDirs& d) { d.write("plan.json", text); }; };
  return {
      {"planTwentyThousandPoints", planFile(plan(manyPoints(20000)))},
      {"planNumbersNear1e308", planFile(plan("[[0, 0], [1.7e308, 0], [1.7e308, 1.7e308], [0, 1.7e308]]"))},
      {"planBoxFar", planFile(plan("[[0, 0], [4, 0], [4, 3], [0, 3]]", "[1e300, 1e300]"))},
      {"planBoxNegative", planFile(plan("[[0, 0], [4, 0], [4, 3], [0, 3]]", "[-1e300, 3.0]"))},
      {"planHuge", planFile(plan("[[0, 0], [5000, 0], [5000, 5000], [0, 5000]]", "[5000, 5000]"))},
      {"planTwoPoints", planFile(plan("[[0, 0], [4, 0]]"))},
      {"planNotNumbers", planFile(plan("[[\"a\", 0], [4, 0], [4, 3], [0, 3]]"))},
      {"planNotJson", planFile("{\"verts\": [[0, 0], ")},
      {"planDevZero", [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "plan.json"); }},
      {"planFolder", [](const CaseDirs& d) { d.write("plan.json/x", "x"); }},
  };
}

AdversarialCase houseCase(const std::string& name, std::vector<std::string> args,
                          std::function<void(const CaseDirs&)> setup) {
  AdversarialCase c;
  c.name = name;
  c.args = std::move(args);
  c.setup = std::move(setup);
  return c;
}

}  // namespace

std::vector<AdversarialCase> houseCases() {
  std::vector<AdversarialCase> out;
  const std::string simLink = "sim:" + std::string(kGoodMap) + "@1,20";
  for (const BadHouse& h : badHouses()) {
    out.push_back(houseCase("pathHouse_" + h.name,
                            {"path", "--house", "{dir}/house", "--from", "room0:3,3", "--to", "room2:3,3"}, h.setup));
    out.push_back(houseCase("export_" + h.name, {"export", "{dir}/house", "--png", "{dir}/out.png"}, h.setup));
    out.push_back(houseCase("connectHouse_" + h.name, {"connect", simLink, "--house", "{dir}/house"}, h.setup));
    out.back().stdinText = "quit\n";
  }
  for (const BadHouse& p : badPlans()) {
    out.push_back(houseCase("simHouse_" + p.name, {"sim-house", "{dir}/plan.json"}, p.setup));
  }
  return out;
}

}  // namespace nxtmap::adversarial
