// Outputs that cannot be written (defects 5, 9, 11 and 12 of issue 15): a device, a folder or a missing
// folder in place of a file; a full disk (/dev/full). A refused write leaves every file as it was (the
// /dev/full device node included); a trailing slash on a house folder is legitimate; a staging folder left by
// a killed save is cleaned up by the next save.
#include <filesystem>
#include <string>
#include <vector>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/Fixtures.hpp"
#include "tests/support/EndedPid.hpp"

namespace nxtmap::adversarial {
namespace {

AdversarialCase refused(const std::string& name, std::vector<std::string> args,
                        std::function<void(const CaseDirs&)> setup = nullptr) {
  AdversarialCase c;
  c.name = name;
  c.args = std::move(args);
  c.setup = std::move(setup);
  return c;
}

AdversarialCase works(const std::string& name, std::vector<std::string> args, std::vector<std::string> creates,
                      std::function<void(const CaseDirs&)> setup = nullptr) {
  AdversarialCase c = refused(name, std::move(args), std::move(setup));
  c.works = true;
  c.creates = std::move(creates);
  c.timeoutS = 120;
  return c;
}

const std::vector<std::pair<std::string, std::string>> kBadTargets = {
    {"DevFull", "/dev/full"}, {"Folder", "{dir}/afolder"}, {"MissingFolder", "{dir}/no/such/out"}};

void makeFolder(const CaseDirs& d) { d.write("afolder/keep", "kept"); }

}  // namespace

std::vector<AdversarialCase> outputCases() {
  std::vector<AdversarialCase> out;
  const std::vector<std::string> sim = {"sim", kGoodMap, "--start", "1,20", "--show", "none"};
  for (const auto& [tag, target] : kBadTargets) {
    auto with = [&](std::vector<std::string> args, const std::string& option, const std::string& suffix) {
      args.push_back(option);
      args.push_back(target + (tag == "MissingFolder" ? suffix : ""));
      return args;
    };
    out.push_back(refused("sim_png" + tag, with(sim, "--png", ".png"), makeFolder));
    out.push_back(refused("sim_save" + tag, with(sim, "--save", ".yaml"), makeFolder));
    out.push_back(refused("simHouse_png" + tag,
                          with({"sim-house", "{src}/worlds/houses/three-rooms.map", "--start", "8,8"}, "--png", ".png"),
                          makeFolder));
    out.push_back(refused("experiments_csv" + tag,
                          with({"experiments", "{src}/worlds/seed-appendix-a"}, "--csv", ".csv"), makeFolder));
    out.back().timeoutS = 120;
    out.push_back(refused("export_png" + tag, with({"export", "{dir}/house"}, "--png", ".png"), [](const CaseDirs& d) {
      houseWith()(d);
      makeFolder(d);
    }));
    out.push_back(refused("emulate_lcd" + tag,
                          with({"emulate", kGoodMap, "--start", "1,20", "--seconds", "1", "--enter-at", "-1",
                                "--firmware", NXTMAP_FIRMWARE_ELF},
                               "--lcd", ".png"),
                          makeFolder));
  }
  // A trailing slash names the same house folder.
  out.push_back(
      works("simHouse_saveTrailingSlash",
            {"sim-house", "{src}/worlds/houses/three-rooms.map", "--start", "8,8", "--save", "{dir}/out/house/"},
            {"out/house/house.yaml"}, [](const CaseDirs& d) { d.write("out/keep", ""); }));
  out.push_back(refused("simHouse_saveMissingParent", {"sim-house", "{src}/worlds/houses/three-rooms.map", "--start",
                                                       "8,8", "--save", "{dir}/no/such/house"}));
  out.push_back(works("simHouse_png",
                      {"sim-house", "{src}/worlds/houses/three-rooms.map", "--start", "8,8", "--png", "{dir}/h.png"},
                      {"h.png"}));
  // A staging folder of a save that was killed is removed by the next save of the same house.
  AdversarialCase stale =
      works("simHouse_saveCleansStaleStaging",
            {"sim-house", "{src}/worlds/houses/three-rooms.map", "--start", "8,8", "--save", "{dir}/out/house"},
            {"out/house/house.yaml"}, [](const CaseDirs& d) {
              d.write("out/house.saving-" + std::to_string(test::endedPid()) + "/house.yaml", "torn");
            });
  stale.check = [](const CaseDirs& d) -> std::string {
    for (const auto& e : std::filesystem::directory_iterator(d.path("out"))) {
      if (e.path().filename().string().find(".saving-") != std::string::npos) return "left: " + e.path().string();
    }
    return "";
  };
  out.push_back(stale);
  return out;
}

}  // namespace nxtmap::adversarial
