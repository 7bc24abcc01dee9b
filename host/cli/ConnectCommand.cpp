#include "host/cli/ConnectCommand.hpp"

#include <CLI/CLI.hpp>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/console/Console.hpp"
#include "host/link/SimTransport.hpp"
#include "host/network/HouseFiles.hpp"

namespace nxtmap::cli {
namespace {
constexpr double kMaxConnectTimeoutS = 3600;  // an hour: --connect-timeout's upper bound
}  // namespace

CLI::App* addConnectCommand(CLI::App& app, ConnectOptions& o) {
  CLI::App* c = app.add_subcommand("connect", "talk to a brick: live map, explore, goto, save (type help inside)");
  c->add_option("link", o.link, "bt:00:16:53:XX:XX:XX, serial:/dev/rfcomm0, tcp:HOST:PORT or sim:WORLD[@COL,ROW]")
      ->required();
  c->add_option("--speed", o.speed, "sim: links only: run the stand-in brick this many times faster (default 1)");
  c->add_option("--connect-timeout", o.connectTimeoutS,
                "seconds to wait for the brick to answer, (0, 3600] (default 20); also the longest a write may wait");
  c->add_flag("!--no-live", o.live, "do not redraw the map while the brick explores");
  c->add_option("--house", o.house,
                "load a saved house directory (nxtmap sim-house / save DIR); its room --room goes to the brick");
  c->add_option("--room", o.room,
                "with --house: the room the brick stands in, by number (default 0); the brick's pose is read in "
                "that room's frame");
  addWorldRunOptions(*c, o.run);
  addGridOption(*c, o.run);
  c->add_option("--seed", o.seed, "sim: links only: random seed of the noise and the start jitter (default 1)");
  return c;
}

int runConnect(const ConnectOptions& o) {
  if (printNoiseListIfAsked(o.run)) return kExitOk;
  link::LinkSpec spec;
  try {
    spec = link::parseLinkSpec(o.link);
  } catch (const link::LinkError& e) {
    throw CliError(std::string("connect: ") + e.what());
  }
  if (!(o.speed > 0 && o.speed <= 1000)) throw CliError("connect: --speed must be in (0, 1000]");
  if (o.speed != 1.0 && spec.kind != link::LinkSpec::Kind::Sim)
    throw CliError("connect: --speed only applies to sim: links");
  const WorldRunOptions defaults;
  if (spec.kind != link::LinkSpec::Kind::Sim &&
      (o.run.noise != defaults.noise || o.run.robot != defaults.robot || o.run.startJitterDeg != 0.0 || o.seed != "1" ||
       o.run.grid != defaults.grid))
    throw CliError(
        "connect: --noise, --robot, --start-jitter, --grid and --seed only apply to sim: links (a real or emulated "
        "brick has its own)");
  link::SimTransportOptions simOptions;
  simOptions.noise = parseNoise(o.run.noise);
  simOptions.seed = parseSeed(o.seed);
  if (o.run.robot != defaults.robot) simOptions.robot = parseRobot(o.run.robot);
  simOptions.startJitterDeg = checkStartJitter(o.run.startJitterDeg);
  simOptions.grid = gridOf(o.run);
  // Checked before any arithmetic: NaN, infinities, huge or negative values would never end the wait.
  if (!(o.connectTimeoutS > 0 && o.connectTimeoutS <= kMaxConnectTimeoutS)) {
    throw CliError("connect: --connect-timeout must be a number of seconds in (0, 3600]");
  }
  // At least 1 ms: the attempt to open the link and each write wait at most this long.
  const int waitMs = std::max(1, static_cast<int>(std::lround(o.connectTimeoutS * 1000.0)));
  // A house is checked whole before anything else happens: a bad one is one message, nothing loaded.
  std::optional<network::HouseLoad> house;
  if (!o.house.empty()) {
    house = network::loadHouse(o.house);
    if (!house->network) throw CliError("connect: --house " + o.house + ": " + house->error);
    const int rooms = static_cast<int>(house->network->rooms().size());
    if (o.room < 0 || o.room >= rooms) {
      throw CliError("connect: --room " + std::to_string(o.room) + ": the house " + o.house + " has rooms 0.." +
                     std::to_string(rooms - 1));
    }
  } else if (o.room != 0) {
    throw CliError("connect: --room needs --house DIR");
  }

  link::LinkRunner::Opener opener;
  if (spec.kind == link::LinkSpec::Kind::Sim) {
    // Load the world now, so a bad world is a clear error rather than an endless retry.
    std::shared_ptr<link::SimTransport> first;
    try {
      first = std::make_shared<link::SimTransport>(spec, o.speed, simOptions);
    } catch (const link::LinkError& e) {
      throw CliError(std::string("connect: ") + e.what());
    }
    opener = [first](const link::WaitLimit&) -> std::unique_ptr<link::Transport> {
      if (!first) throw link::LinkError("the stand-in brick was switched off");
      // The stand-in lives as long as the console: hand out a proxy to the one instance.
      struct Proxy : link::Transport {
        std::shared_ptr<link::SimTransport> t;
        size_t read(uint8_t* b, size_t c, int ms) override { return t->read(b, c, ms); }
        void write(const uint8_t* d, size_t n) override { t->write(d, n); }
        std::string describe() const override { return t->describe(); }
      };
      auto p = std::make_unique<Proxy>();
      p->t = first;
      return p;
    };
  } else {
    opener = [spec](const link::WaitLimit& limit) { return link::openTransport(spec, limit); };
  }

  link::LinkRunner runner(opener, link::SessionConfig{}, 1000, waitMs);
  runner.start();
  console::Console console(runner, o.link);
  if (house) console.useHouse(std::move(*house->network), house->resolutionM, o.room);
  const bool terminal = ::isatty(STDIN_FILENO) != 0;
  // The live map needs a terminal to draw on; commands may come from a script (make demo does that).
  const bool live = o.live && ::isatty(STDOUT_FILENO) != 0;

  // Wait for the Hello to be answered.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(waitMs);
  while (!runner.with([](link::Session& s) { return s.connected() || !s.error().empty(); })) {
    if (std::chrono::steady_clock::now() > deadline) {
      const std::string why = runner.state();
      runner.stop();
      std::ostringstream limit;
      limit << o.connectTimeoutS;
      throw CliError("connect: no answer from the brick on " + o.link + " within " + limit.str() + " s (" + why + ")");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const std::string error = runner.with([](link::Session& s) { return s.error(); });
  if (!error.empty()) {
    runner.stop();
    throw CliError("connect: " + error);
  }
  std::cout << "connected to " << o.link << " (type help for the commands)" << std::endl;
  if (house) {
    try {
      std::cout << console.enterHouseRoom() << std::flush;
    } catch (const console::ConsoleError& e) {
      runner.stop();
      throw CliError(std::string("connect: --house ") + o.house + ": " + e.what());
    }
  }

  int failures = 0;
  std::string line;
  uint64_t drawn = 0;
  auto lastDraw = std::chrono::steady_clock::now();
  // Live map: redraw when bytes arrived, at most 10 times a second (also while a command waits).
  auto redraw = [&] {
    if (!live || runner.changes() == drawn ||
        std::chrono::steady_clock::now() - lastDraw < std::chrono::milliseconds(100))
      return;
    drawn = runner.changes();
    lastDraw = std::chrono::steady_clock::now();
    std::cout << "\033[H\033[2J" << console.renderMap() << console.statusLine() << "\n> " << std::flush;
  };
  console.onWaiting(redraw);
  while (!console.quit()) {
    redraw();
    const std::string note = console.poll();
    if (!note.empty()) std::cout << note << std::flush;
    pollfd p{STDIN_FILENO, POLLIN, 0};
    if (::poll(&p, 1, 50) <= 0) continue;
    if (!std::getline(std::cin, line)) break;
    try {
      const std::string out = console.execute(console::parseConsoleCommand(line));
      std::cout << out << std::flush;
    } catch (const console::ConsoleError& e) {
      printError(e.what());
      ++failures;
    } catch (const std::invalid_argument& e) {
      printError(e.what());
      ++failures;
    }
  }
  runner.stop();
  // In a script, any refused command makes the run fail (exit 2); at a terminal, leaving is fine.
  return (!terminal && failures > 0) ? kExitUsage : kExitOk;
}

}  // namespace nxtmap::cli
