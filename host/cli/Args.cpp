#include "host/cli/Args.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "host/cli/Errors.hpp"
#include "host/mapping/SimDrive.hpp"
#include "host/report/NumberText.hpp"
#include "host/report/TerminalText.hpp"

namespace nxtmap::cli {
namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}
}  // namespace

void printError(const std::string& message) {
  std::string line = report::escapeForTerminal(message);
  while (!line.empty() && line.back() == ' ') line.pop_back();
  std::cout.flush();
  std::cerr << "nxtmap: " << line << std::endl;
}

CellArg parseCell(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  CellArg c;
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos ||
      !report::parseWholeInt(trim(text.substr(0, comma)), c.col) ||
      !report::parseWholeInt(trim(text.substr(comma + 1)), c.row)) {
    throw CliError(option + " must be COL,ROW with two integers (e.g. 1,20), not '" + text + "'");
  }
  return c;
}

uint64_t parseSeed(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 19) {
    throw CliError("--seed must be a whole number 0..9999999999999999999, not '" + text + "'");
  }
  return std::strtoull(t.c_str(), nullptr, 10);
}

sim::Heading parseHeading(const std::string& text) {
  if (text.size() == 1) {
    if (const auto h = sim::headingFromChar(text[0])) return *h;
  }
  throw CliError("--heading must be one of N, E, S, W, not '" + text + "'");
}

sim::NoiseProfile parseNoise(const std::string& text) {
  if (const auto p = sim::noiseProfileByName(text)) return *p;
  throw CliError("--noise must be one of " + joinNames(sim::noiseProfileNames()) + ", not '" + text + "'");
}

mapping::Strategy parseStrategy(const std::string& text) {
  if (const auto s = mapping::strategyByName(text)) return *s;
  throw CliError("--strategy must be one of " + joinNames(mapping::strategyNames()) + ", not '" + text + "'");
}

std::vector<mapping::Strategy> parseStrategies(const std::string& text) {
  if (text == "both" || text == "all") {
    std::vector<mapping::Strategy> all;
    for (const std::string& n : mapping::strategyNames()) all.push_back(*mapping::strategyByName(n));
    return all;
  }
  if (const auto s = mapping::strategyByName(text)) return {*s};
  throw CliError("--strategy must be one of " + joinNames(mapping::strategyNames()) + ", both, not '" + text + "'");
}

double checkRangeM(double rangeM) {
  char buf[160];
  if (!(rangeM > 0.0)) {
    std::snprintf(buf, sizeof buf, "--range-m must be a positive number of metres, not %g", rangeM);
    throw CliError(buf);
  }
  if (rangeM <= 0.05 || rangeM > 2.54) {
    std::snprintf(buf, sizeof buf, "--range-m must lie above 0.05 (the minimum range) and at most 2.54 m, not %g",
                  rangeM);
    throw CliError(buf);
  }
  return rangeM;
}

std::string countProblem(const std::string& text, uint64_t min, uint64_t max) {
  const std::string t = trim(text);
  const std::string expected =
      "must be a whole number " + std::to_string(min) + ".." + std::to_string(max) + ", not '" + text + "'";
  if (t.empty() || t.find_first_not_of("0123456789") != std::string::npos || t.size() > 19) return expected;
  const uint64_t v = std::strtoull(t.c_str(), nullptr, 10);
  return v < min || v > max ? expected : "";
}

// 10^12 expansions take a search on the largest map (4096 x 4096 cells) days: a bigger number is no limit at
// all, a typing error.
std::string maxNodesProblem(const std::string& text) {
  constexpr uint64_t kMaxNodesLimit = 1000000000000ULL;
  const std::string problem = countProblem(text, 1, kMaxNodesLimit);
  return problem.empty() ? problem : problem + " (leave it out for no limit)";
}

sim::World loadWorld(const std::string& path) {
  sim::WorldLoad load = sim::World::load(path);
  if (!load.world) throw CliError(load.error.empty() ? path + ": cannot load the world" : load.error);
  return std::move(*load.world);
}

void checkRangeCoversCell(int cellCm, double rangeM) {
  RangeGeometry g;
  g.cellCm = static_cast<int16_t>(cellCm);
  g.maxCm = static_cast<int16_t>(std::lround(rangeM * 100.0));
  if (g.freeCells() >= 1) return;
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "--range-m %g reaches less than 1.5 of the robot's %d cm cells, so no reading could prove a "
                "neighbouring cell free: use --range-m %d.%02d or more",
                rangeM, cellCm, (3 * cellCm + 1) / 2 / 100, (3 * cellCm + 1) / 2 % 100);
  throw CliError(buf);
}

void checkStart(const sim::World& world, int col, int row, const std::string& where) {
  const std::string cell = std::to_string(col) + "," + std::to_string(row);
  if (!world.inside(col, row)) {
    throw CliError(where + "start " + cell + " lies outside the " + std::to_string(world.width()) + "x" +
                   std::to_string(world.height()) + " world (cols 0.." + std::to_string(world.width() - 1) +
                   ", rows 0.." + std::to_string(world.height() - 1) + ")");
  }
  if (world.blocked(col, row)) throw CliError(where + "start " + cell + " is an obstacle cell of the world");
}

std::string joinNames(const std::vector<std::string>& names, const std::string& separator) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i) out += separator;
    out += names[i];
  }
  return out;
}

bool stdoutIsTerminal() { return ::isatty(STDOUT_FILENO) == 1; }
bool stderrIsTerminal() { return ::isatty(STDERR_FILENO) == 1; }

bool colorWanted() {
  if (!stdoutIsTerminal()) return false;
  if (const char* nc = std::getenv("NO_COLOR"); nc && *nc) return false;
  const char* term = std::getenv("TERM");
  return !(term && std::string(term) == "dumb");
}

}  // namespace nxtmap::cli
