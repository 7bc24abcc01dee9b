#include "host/cli/App.hpp"

#include <CLI/CLI.hpp>

#include <cstring>
#include <iostream>

#include "host/cli/Args.hpp"
#include "host/cli/EmulateCommand.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ExperimentsCommand.hpp"
#include "host/cli/PathCommand.hpp"
#include "host/cli/PathsCommand.hpp"
#include "host/cli/SimCommand.hpp"

namespace nxtmap::cli {

int runCli(int argc, char** argv) {
  CLI::App app{"nxtmap: room mapping with a LEGO NXT robot, in the simulator", "nxtmap"};
  app.require_subcommand(0, 1);
  SimOptions simOptions;
  ExperimentsOptions experimentsOptions;
  CLI::App* sim = addSimCommand(app, simOptions);
  CLI::App* experiments = addExperimentsCommand(app, experimentsOptions);
  EmulateOptions emulateOptions;
  CLI::App* emulate = addEmulateCommand(app, emulateOptions);
  PathOptions pathOptions;
  PathsOptions pathsOptions;
  CLI::App* path = addPathCommand(app, pathOptions);
  CLI::App* paths = addPathsCommand(app, pathsOptions);
  app.footer("Examples:\n  nxtmap sim worlds/seed-appendix-a/occupancy-120.map --start 1,20 --show live\n"
             "  nxtmap emulate worlds/seed-appendix-a/occupancy-120.map --start 1,20 --listen tcp:127.0.0.1:5555\n"
             "  nxtmap experiments worlds/seed-appendix-a --strategy both --csv results.csv --plots plots\n"
             "  nxtmap path worlds/seed-appendix-a/occupancy-120.map --from 1,20 --to 20,1 --algo seed\n"
             "  nxtmap paths worlds/movingai/dao/arena2.map --scen worlds/movingai/dao/arena2.map.scen --algo jps");

  try {
    if (argc > 1 && argv[1][0] != '-') {
      const std::string command = argv[1];
      if (command != sim->get_name() && command != experiments->get_name() && command != path->get_name() &&
          command != paths->get_name() && command != emulate->get_name()) {
        throw CliError("unknown command '" + command +
                       "' (commands: sim, experiments, path, paths, emulate; see nxtmap --help)");
      }
    }
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == 0) return app.exit(e);  // --help
      std::string where;
      if (sim->parsed()) where = "sim: ";
      if (experiments->parsed()) where = "experiments: ";
      if (path->parsed()) where = "path: ";
      if (paths->parsed()) where = "paths: ";
      if (emulate->parsed()) where = "emulate: ";
      throw CliError(where + e.what());
    }
    if (sim->parsed()) return runSim(simOptions);
    if (experiments->parsed()) return runExperiments(experimentsOptions);
    if (path->parsed()) return runPath(pathOptions);
    if (paths->parsed()) return runPaths(pathsOptions);
    if (emulate->parsed()) return runEmulate(emulateOptions);
    std::cout << app.help();
    throw CliError("no command given: use sim, experiments, path, paths or emulate (see nxtmap --help)");
  } catch (const CliError& e) {
    printError(e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    printError(std::string("internal error: ") + e.what());
    return 1;
  }
}

}  // namespace nxtmap::cli
