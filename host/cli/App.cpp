#include "host/cli/App.hpp"

#include <CLI/CLI.hpp>

#include <cstring>
#include <iostream>
#include <optional>
#include <string>

#include "host/cli/Args.hpp"
#include "host/cli/EmulateCommand.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ConnectCommand.hpp"
#include "host/cli/ExportCommand.hpp"
#include "host/cli/ExperimentsCommand.hpp"
#include "host/cli/FlashCommand.hpp"
#include "host/cli/PathCommand.hpp"
#include "host/cli/PathsCommand.hpp"
#include "host/cli/SimCommand.hpp"
#include "host/cli/SimHouseCommand.hpp"
#include "host/log/Log.hpp"

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
  ConnectOptions connectOptions;
  FlashOptions flashOptions;
  CLI::App* connect = addConnectCommand(app, connectOptions);
  CLI::App* flash = addFlashCommand(app, flashOptions);
  SimHouseOptions simHouseOptions;
  CLI::App* simHouse = addSimHouseCommand(app, simHouseOptions);
  ExportOptions exportOptions;
  CLI::App* exportCmd = addExportCommand(app, exportOptions);
  std::string logLevel;  // empty: NXTMAP_LOG or warn
  app.add_option("--log", logLevel,
                 "log messages on stderr from this level up: error, warn (the default), info, debug "
                 "(before the command; NXTMAP_LOG=LEVEL does the same)")
      ->check(CLI::IsMember({"error", "warn", "info", "debug"}));
  app.footer(
      "Examples:\n  nxtmap sim worlds/seed-appendix-a/occupancy-120.map --start 1,20 --show live\n"
      "  nxtmap emulate worlds/seed-appendix-a/occupancy-120.map --start 1,20 --listen tcp:127.0.0.1:5555\n"
      "  nxtmap experiments worlds/seed-appendix-a --strategy both --csv results.csv --plots plots\n"
      "  nxtmap path worlds/seed-appendix-a/occupancy-120.map --from 1,20 --to 20,1 --algo seed\n"
      "  nxtmap paths worlds/movingai/dao/arena2.map --scen worlds/movingai/dao/arena2.map.scen --algo jps\n"
      "  nxtmap connect bt:00:16:53:0A:1B:2C      (or serial:/dev/rfcomm0, tcp:localhost:5000, sim:WORLD)\n"
      "  nxtmap flash build/firmware/nxtmap.bin   (nxtmap flash --restore: LEGO's firmware)");

  try {
    if (argc > 1 && argv[1][0] != '-') {
      const std::string command = argv[1];
      if (command != sim->get_name() && command != experiments->get_name() && command != path->get_name() &&
          command != paths->get_name() && command != connect->get_name() && command != flash->get_name() &&
          command != simHouse->get_name() && command != exportCmd->get_name() && command != emulate->get_name()) {
        throw CliError("unknown command '" + command +
                       "' (commands: sim, experiments, path, paths, sim-house, export, emulate, connect, flash; "
                       "see nxtmap --help)");
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
      if (connect->parsed()) where = "connect: ";
      if (flash->parsed()) where = "flash: ";
      if (simHouse->parsed()) where = "sim-house: ";
      if (exportCmd->parsed()) where = "export: ";
      if (emulate->parsed()) where = "emulate: ";
      throw CliError(where + e.what());
    }
    if (const std::optional<log::Level> level = log::parseLevel(logLevel)) log::setLevel(*level);
    if (sim->parsed()) return runSim(simOptions);
    if (experiments->parsed()) return runExperiments(experimentsOptions);
    if (path->parsed()) return runPath(pathOptions);
    if (paths->parsed()) return runPaths(pathsOptions);
    if (connect->parsed()) return runConnect(connectOptions);
    if (flash->parsed()) return runFlash(flashOptions);
    if (simHouse->parsed()) return runSimHouse(simHouseOptions);
    if (exportCmd->parsed()) return runExport(exportOptions);
    if (emulate->parsed()) return runEmulate(emulateOptions);
    std::cout << app.help();
    throw CliError(
        "no command given: use sim, experiments, path, paths, sim-house, export, emulate, connect or flash "
        "(see nxtmap --help)");
  } catch (const CliError& e) {
    printError(e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    printError(std::string("internal error: ") + e.what());
    return 1;
  }
}

}  // namespace nxtmap::cli
