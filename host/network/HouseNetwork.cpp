#include "host/network/HouseNetwork.hpp"

#include <algorithm>
#include <climits>
#include <deque>
#include <set>

namespace nxtmap::network {

int HouseNetwork::addRoom(RoomNode room) {
  rooms_.push_back(std::move(room));
  return static_cast<int>(rooms_.size()) - 1;
}

void HouseNetwork::addGateway(Gateway g) { gateways_.push_back(std::move(g)); }

int HouseNetwork::roomIndex(const std::string& name) const {
  for (size_t i = 0; i < rooms_.size(); ++i) {
    if (rooms_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

bool HouseNetwork::validate(std::string& error) const {
  std::set<std::string> names;
  for (const RoomNode& r : rooms_) {
    if (r.name.empty()) {
      error = "a room has no name";
      return false;
    }
    if (!names.insert(r.name).second) {
      error = "two rooms are named '" + r.name + "'";
      return false;
    }
  }
  const int n = static_cast<int>(rooms_.size());
  for (size_t i = 0; i < gateways_.size(); ++i) {
    const Gateway& g = gateways_[i];
    const std::string which = "gateway " + std::to_string(i);
    if (g.roomA < 0 || g.roomA >= n || g.roomB < 0 || g.roomB >= n) {
      error = which + " names a room that does not exist";
      return false;
    }
    if (g.roomA == g.roomB) {
      error = which + " joins room '" + rooms_[static_cast<size_t>(g.roomA)].name + "' to itself";
      return false;
    }
    if (g.cellsA.empty() || g.cellsA.size() != g.cellsB.size()) {
      error = which + " needs the same, non-zero number of cells on both sides";
      return false;
    }
    const auto blocked = [&](int room, const std::vector<Cell>& cells) {
      const RoomMap& m = rooms_[static_cast<size_t>(room)].map;
      return std::any_of(cells.begin(), cells.end(), [&](Cell c) { return m.at(c) == CellState::Occupied; });
    };
    if (blocked(g.roomA, g.cellsA) || blocked(g.roomB, g.cellsB)) {
      error = which + " has a cell that its room's map holds as a wall";
      return false;
    }
  }
  return true;
}

std::vector<int> HouseNetwork::roomRoute(int from, int to) const {
  const int n = static_cast<int>(rooms_.size());
  if (from < 0 || to < 0 || from >= n || to >= n) return {};
  std::vector<int> parent(static_cast<size_t>(n), -2);
  std::deque<int> queue{from};
  parent[static_cast<size_t>(from)] = -1;
  while (!queue.empty()) {
    const int r = queue.front();
    queue.pop_front();
    if (r == to) break;
    for (const Gateway& g : gateways_) {
      const int next = g.roomA == r ? g.roomB : (g.roomB == r ? g.roomA : -1);
      if (next < 0 || parent[static_cast<size_t>(next)] != -2) continue;
      parent[static_cast<size_t>(next)] = r;
      queue.push_back(next);
    }
  }
  if (parent[static_cast<size_t>(to)] == -2) return {};
  std::vector<int> route;
  for (int r = to; r != -1; r = parent[static_cast<size_t>(r)]) route.push_back(r);
  std::reverse(route.begin(), route.end());
  return route;
}

std::vector<int> HouseNetwork::gatewaysBetween(int a, int b) const {
  std::vector<int> out;
  for (size_t i = 0; i < gateways_.size(); ++i) {
    const Gateway& g = gateways_[i];
    if ((g.roomA == a && g.roomB == b) || (g.roomA == b && g.roomB == a)) out.push_back(static_cast<int>(i));
  }
  return out;
}

RoomMap HouseNetwork::merged() const {
  if (rooms_.empty()) return RoomMap(0, 0, 0, 0);
  int minX = INT_MAX, minY = INT_MAX, maxX = INT_MIN, maxY = INT_MIN;
  for (const RoomNode& r : rooms_) {
    const RoomMap& m = r.map;
    if (m.width() == 0 || m.height() == 0) continue;
    for (const Cell corner : {Cell{static_cast<int16_t>(m.minX()), static_cast<int16_t>(m.minY())},
                              Cell{static_cast<int16_t>(m.maxX()), static_cast<int16_t>(m.maxY())}}) {
      const Cell h = r.toHouse.apply(corner);
      minX = std::min<int>(minX, h.x);
      minY = std::min<int>(minY, h.y);
      maxX = std::max<int>(maxX, h.x);
      maxY = std::max<int>(maxY, h.y);
    }
  }
  if (minX > maxX) return RoomMap(0, 0, 0, 0);
  const int w = maxX - minX + 1, h = maxY - minY + 1;
  std::vector<int> freeVotes(static_cast<size_t>(w * h), 0), occVotes(static_cast<size_t>(w * h), 0);
  for (const RoomNode& r : rooms_) {
    const RoomMap& m = r.map;
    for (int y = m.minY(); y <= m.maxY(); ++y) {
      for (int x = m.minX(); x <= m.maxX(); ++x) {
        const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
        const CellState s = m.at(c);
        if (s == CellState::Unknown) continue;
        const Cell hc = r.toHouse.apply(c);
        const size_t i = static_cast<size_t>((hc.y - minY) * w + (hc.x - minX));
        (s == CellState::Free ? freeVotes : occVotes)[i]++;
      }
    }
  }
  RoomMap out(minX, minY, w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y * w + x);
      if (freeVotes[i] == 0 && occVotes[i] == 0) continue;
      out.set(Cell{static_cast<int16_t>(minX + x), static_cast<int16_t>(minY + y)},
              occVotes[i] >= freeVotes[i] ? CellState::Occupied : CellState::Free);
    }
  }
  return out;
}

}  // namespace nxtmap::network
