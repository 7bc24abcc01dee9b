// Helpers for protocol tests: a grid with its storage, a PC-side copy that applies deltas,
// and a minimal PC peer that frames packets.
#pragma once
#include <map>
#include <utility>
#include <vector>

#include "common/grid/RoomGrid.hpp"
#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "common/protocol/SeqWindow.hpp"

namespace nxtmap::protocol::test {

template <int W = 64, int H = 64>
struct OwnedGrid {
  uint8_t storage[packedBytes(W, H, 2)] = {};
  uint8_t shadow[packedBytes(W, H, 2)] = {};
  RoomGrid grid{storage, W, H};
};

// The PC's copy of the brick map: known cells by coordinate, cleared when the epoch changes.
struct MirrorMap {
  bool haveEpoch = false;
  uint16_t epoch = 0;
  std::map<std::pair<int, int>, CellState> cells;
  int deltas = 0;

  bool apply(const uint8_t* p, size_t n) {
    MapDeltaReader r(p, n);
    if (!r.validate()) return false;
    if (!haveEpoch || r.header().epoch != epoch) {
      cells.clear();
      epoch = r.header().epoch;
      haveEpoch = true;
    }
    Cell c;
    CellState s;
    while (r.next(c, s)) {
      if (s == CellState::Unknown)
        cells.erase({c.x, c.y});
      else
        cells[{c.x, c.y}] = s;
    }
    ++deltas;
    return true;
  }
  // Whether the copy equals every cell of `grid` (inside its window; outside, both are unknown).
  bool equals(const RoomGrid& grid) const {
    const Bounds w = grid.window();
    size_t known = 0;
    for (int y = w.minY; y <= w.maxY; ++y) {
      for (int x = w.minX; x <= w.maxX; ++x) {
        const CellState s = grid.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
        auto it = cells.find({x, y});
        const CellState mine = it == cells.end() ? CellState::Unknown : it->second;
        if (mine != s) return false;
        if (s != CellState::Unknown) ++known;
      }
    }
    return known == cells.size();
  }
};

// Frames a packet from the PC.
inline std::vector<uint8_t> pcPacket(Op op, uint16_t seq, const SeqWindow& received, const Payload* payload = nullptr) {
  PacketHeader h;
  h.op = op;
  h.flags = seq != 0 ? kFlagReliable : 0;
  h.seq = seq;
  h.ack = received.ack();
  h.ackMask = received.ackMask();
  Frame f;
  encodePacket(h, payload ? payload->bytes : nullptr, payload ? payload->size : 0, f);
  return std::vector<uint8_t>(f.bytes, f.bytes + f.size);
}

}  // namespace nxtmap::protocol::test
