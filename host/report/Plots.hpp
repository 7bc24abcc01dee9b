// Plots: gnuplot PNGs in the manner of the thesis's Chapter 5 figures, ours beside the published:
//   fig5_3.png  learning time vs occupancy (runs occ*) and vs start position (runs start*)
//   fig5_4.png  grid occupancy detection vs occupancy and vs start position
//   fig5_6.png  sensor usage vs occupancy and vs start position
// Each figure is written as <name>.gp + <name>-occ.dat + <name>-start.dat and rendered by gnuplot; every file
// is written whole or not at all (fileio::AtomicFile), the PNG replaced only when gnuplot succeeded.
#pragma once
#include <string>
#include <vector>

#include "host/report/ExperimentTable.hpp"

namespace nxtmap::report {

// The gnuplot executable found on PATH (or /usr/bin/gnuplot), empty when there is none.
std::string findGnuplot();

// Writes the three figures into `dir` (created when missing) for one or more strategies' tables
// over the same scenarios. False with `error` set when gnuplot is missing or fails.
bool writePlots(const std::string& dir, const std::vector<ExperimentTable>& tables, std::vector<std::string>& written,
                std::string& error);

}  // namespace nxtmap::report
