// The realism section of `make bench` (RealismBench.cpp: table 1, presets; RealismFactors.cpp: table 2, one
// factor at a time; RealismLessOne.cpp: table 3, the acceptance's brick less one fact) and what its tables share.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "host/bench/BenchWorlds.hpp"
#include "host/bench/RealismRuns.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/cli/ProgressLine.hpp"
#include "host/sim/Site.hpp"

namespace nxtmap::bench {

// Every world the section runs, loaded once (the sets point into the suites and `sites`).
struct RealismWorlds {
  cli::Suite suite10, suite20;   // worlds/seed-appendix-a at 10 cm (published) and 20 cm cells (brick)
  std::vector<sim::Site> sites;  // worlds/rooms/*.yaml at 20 cm, then the HouseExpo plans at 10 cm
  RealismSet published, brick, furnished, houses;
  // Throws cli::CliError naming the file on any problem.
  void load();
};

// The section: its three tables and its wall time; 0 when every row ran.
int runRealismBench();
// Table 3 alone (`nxtmap-bench less-one`).
int runLessOneBench();
// Table 2 (RealismFactors.cpp).
void factorTable(const RealismWorlds& worlds);

// Table 3 (RealismLessOne.cpp).
void lessOneTable(const RealismWorlds& worlds);

// "+1.5", "-3", "0".
std::string formatDelta(double v, int decimals);
// `v` with its difference from `base` in brackets ("93.2 (-1.5)"), or `v` alone for a base row.
std::string withDelta(double v, double base, int decimals, bool isBase);
// Left-aligned columns, a rule under the head; an empty row prints an empty line.
void printColumns(const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& rows);
// "[SECTION: PART] k of N" on stderr (cli::ProgressLine: rewritten on a terminal, a line a tenth in a log).
std::string progressLabel(const std::string& section, const std::string& part);

}  // namespace nxtmap::bench
