// The body of the protocol fuzz target, shared by the libFuzzer entry (ProtocolFuzz.cpp, `make
// fuzz`) and the corpus replay in `make test` (tests/protocol/FuzzCorpusTest.cpp).
//
// Input bytes go (1) byte by byte into the brick's BrickLink (decoder, packets, commands, LEGO
// direct commands, map bookkeeping) with transmit() between chunks, and (2) into the PC's
// Session. Beyond "no crash, no undefined behaviour", it checks properties: every payload a
// decoder accepts encodes back to the very same bytes (one encoding per message), every frame
// BrickLink sends decodes as a valid telegram, and the decoder never holds more than a frame.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "common/grid/RoomGrid.hpp"
#include "common/protocol/BrickLink.hpp"
#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::fuzz {

// Returns the name of the property that failed, or nullptr.
inline const char* roundTrips(protocol::Op op, const uint8_t* p, size_t n) {
  using namespace protocol;
  Payload again;
  auto same = [&](size_t size) { return size == n && std::memcmp(again.bytes, p, n) == 0; };
  switch (op) {
    case Op::Hello: {
      HelloMsg m;
      if (decodeHello(p, n, m) && !same(encodeHello(m, again))) return "Hello re-encodes differently";
      break;
    }
    case Op::FollowPath: {
      PathMsg m;
      if (decodePath(p, n, m) && !same(encodePath(m, again))) return "FollowPath re-encodes differently";
      break;
    }
    case Op::MapChunk: {
      MapChunkMsg m;
      if (decodeMapChunk(p, n, m) && !same(encodeMapChunk(m, again))) return "MapChunk re-encodes differently";
      break;
    }
    case Op::HelloReply: {
      HelloReplyMsg m;
      if (decodeHelloReply(p, n, m) && !same(encodeHelloReply(m, again))) return "HelloReply re-encodes differently";
      break;
    }
    case Op::Status: {
      StatusMsg m;
      if (decodeStatus(p, n, m) && !same(encodeStatus(m, again))) return "Status re-encodes differently";
      break;
    }
    case Op::Counters: {
      CountersMsg m;
      if (decodeCounters(p, n, m) && !same(encodeCounters(m, again))) return "Counters re-encodes differently";
      break;
    }
    case Op::Pose: {
      PoseMsg m;
      if (decodePose(p, n, m) && !same(encodePose(m, again))) return "Pose re-encodes differently";
      break;
    }
    case Op::PathProgress: {
      PathProgressMsg m;
      if (decodePathProgress(p, n, m) && !same(encodePathProgress(m, again)))
        return "PathProgress re-encodes differently";
      break;
    }
    case Op::NewRoom: {
      NewRoomMsg m;
      if (decodeNewRoom(p, n, m) && !same(encodeNewRoom(m, again))) return "NewRoom re-encodes differently";
      break;
    }
    case Op::Battery: {
      BatteryMsg m;
      if (decodeBattery(p, n, m) && !same(encodeBattery(m, again))) return "Battery re-encodes differently";
      break;
    }
    case Op::MapDelta: {
      MapDeltaReader r(p, n);
      if (r.validate()) {
        Cell c;
        CellState s;
        size_t cells = 0;
        while (r.next(c, s)) {
          if (static_cast<uint8_t>(s) > 2) return "MapDelta yields state 3";
          if (!r.header().window.contains(c) && !r.header().window.empty()) return "MapDelta cell outside its window";
          ++cells;
        }
        if (cells > n * 4) return "MapDelta yields more cells than it holds";
      }
      break;
    }
    default: break;
  }
  return nullptr;
}

// Turns arbitrary bytes into well-framed nxtmap packets with good CRCs, so that mutations reach
// the message decoders and the brick's command handling (random bytes almost never carry a
// valid CRC-32). Each item: [n][op][flags][seq lo][seq hi][ack lo][ack hi][mask lo][mask hi][n payload bytes].
inline std::vector<uint8_t> framedPackets(const uint8_t* data, size_t size) {
  using namespace protocol;
  std::vector<uint8_t> out;
  size_t i = 0;
  while (i + 9 <= size) {
    const size_t n = data[i] % (kMaxPayload + 1);
    if (i + 9 + n > size) break;
    PacketHeader h;
    h.op = static_cast<Op>(data[i + 1]);
    h.flags = data[i + 2];
    h.seq = static_cast<uint16_t>(data[i + 3] | (data[i + 4] << 8));
    h.ack = static_cast<uint16_t>(data[i + 5] | (data[i + 6] << 8));
    h.ackMask = static_cast<uint16_t>(data[i + 7] | (data[i + 8] << 8));
    Frame f;
    if (encodePacket(h, data + i + 9, n, f)) out.insert(out.end(), f.bytes, f.bytes + f.size);
    i += 9 + n;
  }
  return out;
}

inline const char* runStream(const uint8_t* data, size_t size);

inline const char* runProtocolInput(const uint8_t* data, size_t size) {
  if (const char* bad = runStream(data, size)) return bad;
  const std::vector<uint8_t> framed = framedPackets(data, size);
  return runStream(framed.data(), framed.size());
}

inline const char* runStream(const uint8_t* data, size_t size) {
  using namespace protocol;
  // (1) The brick.
  static uint8_t storage[packedBytes(64, 64, 2)];
  static uint8_t shadow[packedBytes(64, 64, 2)];
  std::memset(storage, 0, sizeof(storage));
  RoomGrid grid(storage, 64, 64);
  (void)grid.set(Cell{0, 0}, CellState::Free);
  (void)grid.set(Cell{1, 0}, CellState::Occupied);
  BrickLink link(grid, shadow, BrickLinkConfig{});
  BrickReport report;
  FrameDecoder check;
  uint32_t now = 0;
  for (size_t i = 0; i < size; ++i) {
    link.receive(data[i]);
    if (link.mapSync().inFlight() > MapSync::kSlots) return "too many deltas in flight";
    if (i % 16 == 15 || i + 1 == size) {
      now += 37;
      Command c;
      while (link.nextCommand(c)) {
        if (c.kind == CommandKind::FollowPath && (c.path.count == 0 || c.path.count > kMaxPathCells))
          return "bad path handed over";
        if (c.kind == CommandKind::MapChunk) {
          for (uint16_t k = 0; k < c.chunk.count; ++k) (void)grid.set(c.chunk.cellOf(k), c.chunk.state(k));
        }
      }
      Frame f;
      int frames = 0;
      while (link.transmit(now, report, f) && ++frames < 64) {
        Telegram t;
        for (uint8_t k = 0; k < f.size; ++k) check.push(f.bytes[k]);
        if (!check.pop(t)) return "BrickLink sent a frame the decoder refuses";
        if (check.buffered() != 0) return "BrickLink sent trailing bytes";
      }
    }
  }
  // Every telegram in the input: decoders either refuse it or read it back canonically.
  FrameDecoder d;
  Telegram t;
  for (size_t i = 0; i < size; ++i) {
    d.push(data[i]);
    if (d.buffered() > kMaxFrame) return "decoder holds more than a frame";
    while (d.pop(t)) {
      if (!telegramValid(t.bytes, t.size)) return "decoder delivered an invalid telegram";
      PacketView v;
      if (parsePacket(t, v)) {
        if (const char* bad = roundTrips(v.header.op, v.payload, v.payloadSize)) return bad;
      }
    }
  }
  // Raw payload decoders on the whole input as well.
  for (uint8_t op = 0; op < 0x50; ++op) {
    if (const char* bad = roundTrips(static_cast<Op>(op), data, size)) return bad;
  }
  // (2) The PC.
  link::Session pc(link::SessionConfig{1, 250, 250});
  pc.receive(data, size, 10);
  (void)pc.transmit(20);
  return nullptr;
}

}  // namespace nxtmap::fuzz
