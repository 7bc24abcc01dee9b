// Bad options and arguments on good worlds: numbers that are not numbers, out of range, negative counts,
// cells outside the map, unknown names, and names that would drive the terminal.
#include <string>
#include <vector>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/Fixtures.hpp"

namespace nxtmap::adversarial {
namespace {

AdversarialCase refused(const std::string& name, std::vector<std::string> args) {
  AdversarialCase c;
  c.name = name;
  c.args = std::move(args);
  return c;
}

// One case per bad value of `option`, on `base` (a whole good command without that option).
void eachValue(std::vector<AdversarialCase>& out, const std::string& prefix, const std::vector<std::string>& base,
               const std::string& option, const std::vector<std::pair<std::string, std::string>>& values) {
  for (const auto& [tag, value] : values) {
    std::vector<std::string> args = base;
    args.push_back(option);
    args.push_back(value);
    out.push_back(refused(prefix + "_" + tag, args));
  }
}

const std::vector<std::pair<std::string, std::string>> kNotFinite = {
    {"Nan", "nan"}, {"Inf", "inf"}, {"Huge", "1e300"}, {"Negative", "-1"}, {"Text", "abc"}, {"Empty", ""}};

}  // namespace

std::vector<AdversarialCase> argumentCases() {
  std::vector<AdversarialCase> out;
  const std::vector<std::string> sim = {"sim", kGoodMap, "--start", "1,20", "--show", "none"};
  const std::vector<std::string> path = {"path", kGoodMap, "--from", "1,20", "--to", "18,3", "--draw", "never"};
  eachValue(out, "sim_rangeM", sim, "--range-m", kNotFinite);
  eachValue(out, "sim_delayMs", sim, "--delay-ms", {{"Negative", "-5"}, {"Text", "soon"}});
  eachValue(out, "sim_start", {"sim", kGoodMap, "--show", "none"}, "--start",
            {{"Outside", "999,999"},
             {"Negative", "-1,-1"},
             {"Wall", "0,0"},
             {"Overflow", "99999999999,1"},
             {"Text", "here"},
             {"OneNumber", "5"}});
  eachValue(out, "sim_heading", sim, "--heading", {{"Bad", "NE"}});
  eachValue(out, "sim_noise", sim, "--noise", {{"Bad", "loud"}});
  eachValue(out, "sim_strategy", sim, "--strategy", {{"Bad", "random"}});
  eachValue(out, "sim_show", sim, "--show", {{"Bad", "movie"}});
  eachValue(out, "path_maxNodes", path, "--max-nodes", {{"Negative", "-1"}, {"Zero", "0"}, {"Text", "many"}});
  eachValue(out, "paths_maxNodes", {"paths", kGoodMap, "--scen", "{src}/tests/adversarial/data/small.scen"},
            "--max-nodes", {{"Negative", "-1"}, {"Zero", "0"}, {"Hex", "0x10"}});
  eachValue(out, "path_clearance", path, "--clearance", {{"Negative", "-1"}, {"Huge", "1000000000"}});
  eachValue(out, "path_algo", path, "--algo", {{"Bad", "bfs"}});
  eachValue(out, "path_draw", path, "--draw", {{"Bad", "sometimes"}});
  eachValue(out, "path_label", path, "--label",
            {{"NoCell", "chair"},
             {"Outside", "chair=999,999"},
             {"Negative", "chair=1,1,-2,3"},
             {"Escape", "\x1b[2Jchair=1,1"}});
  eachValue(out, "path_to", {"path", kGoodMap, "--from", "1,20"}, "--to",
            {{"Outside", "99,99"}, {"UnknownLabel", "near:nothing"}, {"Text", "there"}});
  eachValue(out, "experiments_seeds", {"experiments", "{src}/worlds/seed-appendix-a"}, "--seeds",
            {{"Zero", "0"}, {"Negative", "-3"}, {"Huge", "1000000000"}});
  eachValue(out, "connect_timeout", {"connect", "sim:" + std::string(kGoodMap) + "@1,20"}, "--connect-timeout",
            kNotFinite);
  eachValue(out, "connect_speed", {"connect", "sim:" + std::string(kGoodMap) + "@1,20"}, "--speed",
            {{"Nan", "nan"}, {"Zero", "0"}, {"Negative", "-2"}});
  eachValue(out, "emulate_seconds", {"emulate", kGoodMap, "--start", "1,20", "--firmware", NXTMAP_FIRMWARE_ELF},
            "--seconds", {{"Nan", "nan"}, {"Negative", "-1"}, {"Inf", "inf"}});
  eachValue(out, "export_cellPx", {"export", "{dir}/house"}, "--cell-px", {{"Zero", "0"}, {"Big", "33"}});
  for (size_t i = out.size() - 2; i < out.size(); ++i) out[i].setup = houseWith();
  out.push_back(refused("unknownCommand", {"mapit"}));
  out.push_back(refused("escapeInFileName", {"sim", "{dir}/\x1b]0;owned\x07\x1b[2J.map", "--start", "1,1"}));
  out.push_back(refused("escapeInCommand", {"\x1b[31mred"}));
  out.push_back(refused("paths_scenMissing", {"paths", kGoodMap, "--scen", "{dir}/none.scen"}));
  out.push_back(refused("paths_scenDevZero", {"paths", kGoodMap, "--scen", "{dir}/zero.scen"}));
  out.back().setup = [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "zero.scen"); };
  out.push_back(refused("flash_imageDevZero", {"flash", "{dir}/zero.bin"}));
  out.back().setup = [](const CaseDirs& d) { symlinkTo(d, "/dev/zero", "zero.bin"); };
  out.push_back(refused("flash_imageFolder", {"flash", "{dir}"}));
  return out;
}

}  // namespace nxtmap::adversarial
