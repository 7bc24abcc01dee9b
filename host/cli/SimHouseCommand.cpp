#include "host/cli/SimHouseCommand.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {
bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
}  // namespace

CLI::App* addSimHouseCommand(CLI::App& app, SimHouseOptions& o) {
  CLI::App* c = app.add_subcommand("sim-house", "map a house room by room in the simulator");
  c->add_option("world", o.world, "world: HouseExpo .json plan, Moving AI .map or ROS map_server .yaml")->required();
  c->add_option("--start", o.start, "start cell COL,ROW (col right, row down); optional for a .json plan");
  c->add_option("--heading", o.heading, "initial heading N, E, S or W (default N)");
  c->add_option("--range-m", o.rangeM, "trusted maximum sensor range in metres (default 1)");
  c->add_option("--noise", o.noise, "noise profile: none, typical, harsh (default none)");
  c->add_option("--seed", o.seed, "random seed of the noise (default 1)");
  c->add_option("--strategy", o.strategy, "exploration strategy per room: propagation, frontier (default frontier: fewer turns, so the pose holds better across rooms)");
  c->add_option("--save", o.save, "directory to save the house in (ROS map per room + house.yaml)");
  return c;
}

int runSimHouse(const SimHouseOptions& o) {
  house::HouseConfig config;
  config.heading = parseHeading(o.heading);
  config.rangeM = checkRangeM(o.rangeM);
  config.noise = parseNoise(o.noise);
  config.seed = parseSeed(o.seed);
  config.strategy = parseStrategy(o.strategy);
  std::optional<house::HousePlan> plan;
  std::optional<sim::World> loaded;
  if (endsWith(o.world, ".json")) {
    house::HousePlanLoad l = house::loadHouseExpo(o.world);
    if (!l.plan) throw CliError(l.error);
    plan = std::move(l.plan);
  } else {
    loaded = loadWorld(o.world);
  }
  const sim::World& world = plan ? plan->world : *loaded;
  if (!o.start.empty()) {
    const CellArg s = parseCell(o.start, "--start");
    config.startCol = s.col;
    config.startRow = s.row;
  } else if (!plan || !house::defaultStart(*plan, config.startCol, config.startRow)) {
    throw CliError("sim-house: --start COL,ROW is required for this world");
  }
  checkRangeCoversCell(world, config.rangeM);
  checkStart(world, config.startCol, config.startRow, "");
  std::string saveError;  // --save is checked before the run, so a bad target does not cost the mapping run
  if (!o.save.empty() && !network::checkHouseTarget(o.save, saveError)) throw CliError(saveError);

  house::HouseMapper mapper(world, config);
  mapper.run();
  if (plan) house::labelRoomsFromPlan(mapper, *plan);
  const house::HouseScore s = house::scoreHouse(mapper);
  const house::HouseCounters& c = mapper.counters();
  const auto num = [](double v) { return report::formatNumber(v, 1); };
  std::ostringstream out;
  out << "house            " << (plan ? plan->id : world.name()) << " " << world.width() << "x" << world.height()
      << ", start " << config.startCol << "," << config.startRow << " heading " << o.heading << ", strategy "
      << mapping::strategyName(config.strategy) << ", noise " << config.noise.name << ", seed " << config.seed << "\n";
  for (const network::RoomNode& r : mapper.network().rooms()) {
    out << "  " << r.name << "  " << r.map.width() << "x" << r.map.height() << " cells, "
        << r.map.count(CellState::Free) << " free, origin at house cell " << r.toHouse.x() << "," << r.toHouse.y()
        << ", turned " << 90 * r.toHouse.quarterTurns() << " deg\n";
  }
  for (const network::Gateway& g : mapper.network().gateways()) {
    const auto& rooms = mapper.network().rooms();
    out << "  gateway " << rooms[static_cast<size_t>(g.roomA)].name << " <-> " << rooms[static_cast<size_t>(g.roomB)].name
        << ", " << g.cellsA.size() << " cells\n";
  }
  out << "rooms            " << s.rooms;
  if (plan) {
    const house::PlanCoverage pc = house::planCoverage(mapper, *plan);
    out << " (plan: " << plan->roomNum << " rooms; " << pc.covered << " of " << pc.reachable
        << " reachable plan rooms mapped to >= 90 %)";
  }
  out << "\ngateways         " << s.gateways << " (exits found " << mapper.exitsFound() << ", not passed "
      << mapper.exitsUnreached() << ", openings onto unmapped space explored " << mapper.openingsTried() << ")\n"
      << "agreement        " << num(s.agreementPct()) << " % of " << s.observable
      << " observable cells (unknown " << s.unknown << ", wrong " << s.wrong << "; wrong elsewhere "
      << s.wrongElsewhere << ")\n"
      << "time units       " << num(c.timeUnits()) << " (between rooms: " << c.travel.cellsMoved << " cells; "
      << "relocalisations " << mapper.relocalisations() << "; start room moved by the start readings "
      << mapper.startShift().x << "," << mapper.startShift().y << ")\n"
      << "sensor requests  " << c.sensorRequests() << "\n"
      << "raw samples      " << c.explore.rawSamples + c.travel.rawSamples << "\n";
  std::cout << out.str() << std::flush;
  if (!o.save.empty()) {
    std::string error;
    if (!network::saveHouse(mapper.network(), world.resolutionM(), o.save, error)) throw CliError(error);
    std::cout << "saved            " << o.save << " (" << mapper.network().rooms().size() << " room maps + "
              << network::kHouseFileName << ")\n";
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
