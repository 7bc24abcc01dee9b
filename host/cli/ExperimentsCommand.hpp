// `nxtmap experiments DIR ...`: every run of DIR/scenarios.tsv, side by side with the published
// figures; optional CSV, Markdown and gnuplot figures.
#pragma once
#include <string>

#include "host/cli/SiteFiles.hpp"

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct ExperimentsOptions {
  std::string dir;
  std::string csv;  // --strategy both: FILE-<strategy>.csv per strategy
  std::string markdown;
  std::string plots;    // directory
  WorldRunOptions run;  // --noise, --robot (brick: the layouts scaled to 20 cm cells), --start-jitter, --grid
  int seeds = 1;
  std::string strategy = "propagation";  // or frontier, both
  bool afterFirstOuting = false;         // --after-first-outing (SuiteSettings::afterFirstOuting)
};

CLI::App* addExperimentsCommand(CLI::App& app, ExperimentsOptions& options);

// Runs it; throws CliError on bad input. Returns the exit code.
int runExperiments(const ExperimentsOptions& options);

}  // namespace nxtmap::cli
