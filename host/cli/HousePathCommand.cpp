#include "host/cli/HousePathCommand.hpp"

#include <iostream>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/network/HouseRoute.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

// "ROOM:C,R" -> room index and room-frame cell; the cell must be a free cell of the room's map.
network::RoomPoint parseRoomCell(const network::HouseNetwork& h, const std::string& text, const std::string& option) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0) {
    throw CliError(option + " must be ROOM:COL,ROW (e.g. room0:12,30), not '" + text + "'");
  }
  const std::string name = text.substr(0, colon);
  const int room = h.roomIndex(name);
  if (room < 0) {
    std::string names;
    for (const network::RoomNode& r : h.rooms()) names += (names.empty() ? "" : ", ") + r.name;
    throw CliError(option + ": no room '" + name + "' in the house (rooms: " + names + ")");
  }
  const CellArg c = parseCell(text.substr(colon + 1), option);
  const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
  if (c.col < 0 || c.row < 0 || c.col >= m.width() || c.row >= m.height()) {
    throw CliError(option + " " + text + " is outside the room's map (" + std::to_string(m.width()) + "x" +
                   std::to_string(m.height()) + " cells)");
  }
  const Cell cell = network::mapCellToRoom(m, c.col, c.row);
  if (!m.isFree(cell)) throw CliError(option + " " + text + " is not a free cell of the room's map");
  return network::RoomPoint{room, cell};
}

std::string roomCellText(const network::HouseNetwork& h, int room, Cell c) {
  const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
  int col, row;
  network::roomCellToMap(m, c, col, row);
  return h.rooms()[static_cast<size_t>(room)].name + ":" + std::to_string(col) + "," + std::to_string(row);
}

}  // namespace

int runHousePath(const PathOptions& o) {
  const auto algorithm = plan::algorithmByName(o.algo);
  if (!algorithm) throw CliError("--algo must be one of seed, astar, jps, dijkstra, not '" + o.algo + "'");
  if (!o.map.empty()) throw CliError("path: give either a MAP or --house DIR, not both");
  if (!o.labels.empty() || o.clearance != 0 || o.throughUnknown || o.maxNodes != 0) {
    throw CliError("path --house: --label, --clearance, --through-unknown and --max-nodes apply to one map only");
  }
  const network::HouseLoad l = network::loadHouse(o.house);
  if (!l.network) throw CliError(l.error);
  const network::HouseNetwork& h = *l.network;
  const network::RoomPoint from = parseRoomCell(h, o.from, "--from");
  network::RoomPoint to;
  std::string label;
  if (o.to.rfind("near:", 0) == 0) {
    label = o.to.substr(5);
    network::RoomPoint at;
    if (!network::findLabel(h, label, at)) {
      std::string names;
      for (const network::RoomNode& r : h.rooms()) {
        for (const auto& kv : r.labels) names += (names.empty() ? "" : ", ") + kv.first;
      }
      throw CliError("--to: unknown label '" + label + "' (labels: " + (names.empty() ? "none" : names) + ")");
    }
  } else {
    to = parseRoomCell(h, o.to, "--to");
  }
  const network::HouseRoute r = network::planHouseRoute(h, from, to, *algorithm, label);
  if (!r.found) throw CliError("no route: " + r.error);
  std::ostringstream out;
  std::string rooms;
  for (const int room : r.rooms) rooms += (rooms.empty() ? "" : " -> ") + h.rooms()[static_cast<size_t>(room)].name;
  const network::HouseLeg& last = r.legs.back();
  out << "algorithm        " << plan::algorithmName(*algorithm) << " in each room, rooms over gateways\n"
      << "from             " << roomCellText(h, from.room, from.cell) << "\n"
      << "to               " << roomCellText(h, last.room, last.cells.back())
      << (label.empty() ? "" : " (next to " + label + ")") << "\n"
      << "rooms            " << rooms << "\n";
  for (const network::HouseLeg& leg : r.legs) {
    out << "  in " << h.rooms()[static_cast<size_t>(leg.room)].name << ": "
        << roomCellText(h, leg.room, leg.cells.front()) << " -> " << roomCellText(h, leg.room, leg.cells.back()) << ", "
        << leg.cells.size() - 1 << " moves\n";
  }
  out << "length           " << report::formatNumber(r.length, 3) << " cells ("
      << report::formatNumber(r.length * l.resolutionM, 2) << " m)\n"
      << "nodes expanded   " << r.nodesExpanded << "\n";
  std::cout << out.str() << std::flush;
  return kExitOk;
}

}  // namespace nxtmap::cli
