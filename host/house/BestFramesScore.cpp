#include "host/house/BestFramesScore.hpp"

#include "host/network/HouseNetwork.hpp"

namespace nxtmap::house {
namespace {

network::RoomTransform moved(const network::RoomTransform& t, Cell by) {
  return network::RoomTransform::fromParts(t.x() + by.x, t.y() + by.y, t.quarterTurns());
}

// The best move of room k (each axis within +-maxShift of its original frame `from`) with the other
// rooms where `copy` has them; keeps the current move unless another agrees strictly better.
Cell bestMoveOf(size_t k, const network::RoomTransform& from, Cell current, int maxShift, const HouseInWorld& view,
                const sim::Observability& obs, network::HouseNetwork& copy, int& agree) {
  network::RoomTransform& frame = copy.rooms()[k].toHouse;
  Cell best = current;
  for (int dy = -maxShift; dy <= maxShift; ++dy) {
    for (int dx = -maxShift; dx <= maxShift; ++dx) {
      const Cell by{static_cast<int16_t>(dx), static_cast<int16_t>(dy)};
      if (by == current) continue;
      frame = moved(from, by);
      const int a = scoreHouse(view, obs).agree;
      if (a > agree) {
        agree = a;
        best = by;
      }
    }
  }
  frame = moved(from, best);
  return best;
}

}  // namespace

BestFramesScore scoreWithBestFrames(const HouseInWorld& house, int maxShift) {
  network::HouseNetwork copy = *house.network;
  HouseInWorld view = house;
  view.network = &copy;
  const std::vector<network::RoomNode>& rooms = house.network->rooms();
  BestFramesScore out;
  out.shifts.assign(rooms.size(), Cell{0, 0});
  const sim::Observability obs = observabilityOf(view);
  int agree = scoreHouse(view, obs).agree;
  bool movedAny = true;
  while (movedAny && out.passes < BestFramesScore::kMaxPasses) {
    ++out.passes;
    movedAny = false;
    for (size_t k = 0; k < rooms.size(); ++k) {
      const Cell before = out.shifts[k];
      out.shifts[k] = bestMoveOf(k, rooms[k].toHouse, before, maxShift, view, obs, copy, agree);
      movedAny = movedAny || !(out.shifts[k] == before);
    }
  }
  out.score = scoreHouse(view, obs);
  return out;
}

}  // namespace nxtmap::house
