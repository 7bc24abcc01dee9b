// Args: parsing and checking the console's option values; every failure throws CliError.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "host/mapping/Strategy.hpp"
#include "host/sim/Heading.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::cli {

struct CellArg {
  int col = 0, row = 0;
};

// "C,R" with two integers (spaces around them tolerated).
CellArg parseCell(const std::string& text, const std::string& option);
// A non-negative whole number.
uint64_t parseSeed(const std::string& text);
sim::Heading parseHeading(const std::string& text);
sim::NoiseProfile parseNoise(const std::string& text);
mapping::Strategy parseStrategy(const std::string& text);
// A strategy name or "both" (every strategy, propagation first).
std::vector<mapping::Strategy> parseStrategies(const std::string& text);
// A trusted maximum range in metres: above the 5 cm minimum, within the sonar's reach.
double checkRangeM(double rangeM);

// "" when `text` is a count min..max in decimal digits (spaces around tolerated), otherwise why not: a check for
// CLI11 options, run on the text before it is converted (CLI11 would take "-1" as the largest count).
std::string countProblem(const std::string& text, uint64_t min, uint64_t max);
// The check of --max-nodes (path, paths): 1..10^12 expansions, or the option left out for no limit.
std::string maxNodesProblem(const std::string& text);

// World::load, its error text on failure.
sim::World loadWorld(const std::string& path);
// The trusted range must cover 1.5 of the robot's cells (RangeGeometry::freeCells() >= 1: the adjacent cell
// wholly); otherwise no reading proves a neighbour free and the robot maps next to nothing.
void checkRangeCoversCell(int cellCm, double rangeM);
// The start must be a free cell inside the world.
void checkStart(const sim::World& world, int col, int row, const std::string& where);

std::string joinNames(const std::vector<std::string>& names, const std::string& separator = ", ");

bool stdoutIsTerminal();
bool stderrIsTerminal();
// ANSI colour on stdout: a terminal, NO_COLOR unset and TERM not "dumb".
bool colorWanted();

}  // namespace nxtmap::cli
