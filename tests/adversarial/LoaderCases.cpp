// Bad worlds for every command that loads one (defects 1, 6, 7 and 11 of issue 15 among them): unusable
// resolutions and origins, devices and folders in place of files, endless or huge files, broken formats.
#include <string>
#include <vector>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/Fixtures.hpp"

namespace nxtmap::adversarial {
namespace {

struct BadWorld {
  std::string name;
  std::string arg;  // the world argument
  std::function<void(const CaseDirs&)> setup;
};

std::vector<BadWorld> badWorlds() {
  const auto none = [](const CaseDirs&) {};
  return {
      {"missing", "{dir}/nowhere.map", none},
      {"folder", "{dir}/afolder", [](const CaseDirs& d) { d.write("afolder/x", "x"); }},
      {"folderNamedMap", "{dir}/room.map", [](const CaseDirs& d) { d.write("room.map/x", "x"); }},
      {"devZeroMap", "{dir}/zero.map", [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "zero.map"); }},
      {"devZeroYaml", "{dir}/zero.yaml", [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "zero.yaml"); }},
      {"emptyMap", "{dir}/empty.map", [](const CaseDirs& d) { d.write("empty.map", ""); }},
      {"binaryMap", "{dir}/bin.map",
       [](const CaseDirs& d) {
         d.write("bin.map", std::string("\x7f"
                                        "ELF\0\1\2",
                                        7));
       }},
      {"hugeMapHeader", "{dir}/huge.map",
       [](const CaseDirs& d) { d.write("huge.map", "type octile\nheight 1000000000\nwidth 1000000000\nmap\n@@\n"); }},
      {"shortMapRows", "{dir}/short.map",
       [](const CaseDirs& d) { d.write("short.map", "type octile\nheight 4\nwidth 6\nmap\n@@@@@@\n@..\n"); }},
      {"resolutionTiny", "{dir}/w.yaml", rosWith("resolution: 0.004")},
      {"resolutionDenormal", "{dir}/w.yaml", rosWith("resolution: 1e-300")},
      {"resolutionHuge", "{dir}/w.yaml", rosWith("resolution: 1e300")},
      {"resolutionZero", "{dir}/w.yaml", rosWith("resolution: 0")},
      {"resolutionNegative", "{dir}/w.yaml", rosWith("resolution: -0.1")},
      {"resolutionNan", "{dir}/w.yaml", rosWith("resolution: .nan")},
      {"resolutionText", "{dir}/w.yaml", rosWith("resolution: fine")},
      {"originNan", "{dir}/w.yaml", rosWith("origin: [.nan, 0.0, 0.0]")},
      {"originInf", "{dir}/w.yaml", rosWith("origin: [0.0, .inf, 0.0]")},
      {"originShort", "{dir}/w.yaml", rosWith("origin: [0.0]")},
      {"negateText", "{dir}/w.yaml", rosWith("negate: perhaps")},
      {"thresholdsSwapped", "{dir}/w.yaml", rosWith("free_thresh: 0.9")},
      {"imageDevZero", "{dir}/w.yaml",
       [](const CaseDirs& d) {
         writeRosMap(d, "w",
                     "image: zero.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
         symlinkTo(d, "/dev/zero", "zero.pgm");
       }},
      {"imageFolder", "{dir}/w.yaml", rosWith("image: .")},
      {"imageMissing", "{dir}/w.yaml", rosWith("image: nothing-here.pgm")},
      {"imageHugeHeader", "{dir}/w.yaml",
       [](const CaseDirs& d) {
         writeRosMap(d, "w",
                     "image: big.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
                     "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
         d.write("big.pgm", "P5\n100000 100000\n255\n\x01\x02");
       }},
      {"yamlNotAMap", "{dir}/list.yaml", [](const CaseDirs& d) { d.write("list.yaml", "- 1\n- 2\n"); }},
      {"yamlSyntax", "{dir}/bad.yaml", [](const CaseDirs& d) { d.write("bad.yaml", "image: [unclosed\n"); }},
      {"unknownExtension", "{dir}/room.txt", [](const CaseDirs& d) { d.write("room.txt", "hello\n"); }},
  };
}

AdversarialCase withCommand(const BadWorld& w, const std::string& command, std::vector<std::string> rest) {
  AdversarialCase c;
  c.name = command + "_" + w.name;
  for (char& ch : c.name) {
    if (ch == '-') ch = '_';
  }
  c.args = {command, w.arg};
  c.args.insert(c.args.end(), rest.begin(), rest.end());
  c.setup = w.setup;
  return c;
}

}  // namespace

std::vector<AdversarialCase> loaderCases() {
  std::vector<AdversarialCase> out;
  for (const BadWorld& w : badWorlds()) {
    out.push_back(withCommand(w, "sim", {"--start", "1,1", "--show", "none"}));
    out.push_back(withCommand(w, "path", {"--from", "1,1", "--to", "2,2", "--draw", "never"}));
    out.push_back(withCommand(w, "sim-house", {"--start", "1,1"}));
  }
  for (const BadWorld& w : {badWorlds()[1], badWorlds()[3], badWorlds()[9], badWorlds()[21]}) {
    out.push_back(withCommand(w, "emulate", {"--start", "1,1", "--seconds", "1", "--firmware", NXTMAP_FIRMWARE_ELF}));
  }
  // The firmware image itself.
  const std::vector<std::pair<std::string, std::function<void(const CaseDirs&)>>> badFirmware = {
      {"DevZero", [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "fw.elf"); }},
      {"Folder", [](const CaseDirs& d) { d.write("fw.elf/x", "x"); }},
      {"Empty", [](const CaseDirs& d) { d.write("fw.elf", ""); }},
      {"NotElf", [](const CaseDirs& d) { d.write("fw.elf", std::string(4096, 'A')); }},
      {"TruncatedElf",
       [](const CaseDirs& d) {
         d.write("fw.elf", std::string("\x7f"
                                       "ELF\1\1\1",
                                       7));
       }},
      {"Missing", [](const CaseDirs&) {}},
  };
  for (const auto& [name, setup] : badFirmware) {
    AdversarialCase c;
    c.name = "emulate_firmware" + name;
    c.args = {"emulate", kGoodMap, "--start", "1,20", "--seconds", "1", "--firmware", "{dir}/fw.elf"};
    c.setup = setup;
    out.push_back(c);
  }
  return out;
}

}  // namespace nxtmap::adversarial
