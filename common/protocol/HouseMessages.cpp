#include "common/protocol/HouseMessages.hpp"

#include "common/protocol/FieldIo.hpp"

namespace nxtmap::protocol {
namespace {

// `outward` crosses the doorway and one step from `inside` enters it.
bool crossesFrom(const DoorwayMsg& door, Dir outward, Cell inside) {
  return isVertical(outward) == door.alongX && door.contains(advance(inside, outward));
}

// A reading in two bytes: cm, then status (low nibble) and samples (high nibble). A reading the
// bytes cannot hold (cm outside 0..255, samples over 15) is not encoded.
bool readingBytes(FieldWriter& io, const RangeReading& m) {
  if (m.cm < 0 || m.cm > kMaxReadingCm || m.samples > 0xF) return false;
  const uint8_t cm = static_cast<uint8_t>(m.cm), status = static_cast<uint8_t>(m.status);
  return io.u8(cm) && io.nibbles(status, m.samples, 0, 0xF);
}
bool readingBytes(FieldReader& io, RangeReading& m) {
  uint8_t cm = 0, status = 0;
  if (!io.u8(cm) || !io.nibbles(status, m.samples, 0, RangeFilter::kMaxSamples)) return false;
  if (status > static_cast<uint8_t>(RangeStatus::Inconsistent)) return false;
  m.cm = cm;
  m.status = static_cast<RangeStatus>(status);
  return true;
}

}  // namespace

template <>
struct Layout<DoorwayMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.cell(m.first) && io.u8In(m.width, 1, kMaxDoorwayWidth) && io.u8In(m.depth, 1, kMaxDoorwayDepth) &&
           io.flag(m.alongX) && io.check([&] { return coordOk(m.cell(m.width - 1, m.depth - 1)); });
  }
};
template <>
struct Layout<ExploreMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.enum8(m.strategy, ExploreStrategy::Frontier) && io.flag(m.confine);
  }
};
template <>
struct Layout<GoToMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.goalId) && io.cell(m.target);
  }
};
template <>
struct Layout<EnterRoomMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.roomId) && io.enum8(m.strategy, ExploreStrategy::Frontier) && io.part(m.door) &&
           io.dir(m.outward) && io.cell(m.inside) && io.check([&] { return crossesFrom(m.door, m.outward, m.inside); });
  }
};
template <>
struct Layout<ScanMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16In(m.scanId, 1, 0xFFFF);
  }
};
template <>
struct Layout<RangeReading> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return readingBytes(io, m);
  }
};
template <>
struct Layout<ReadingsMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    if (!(io.u16(m.scanId) && io.cell(m.scanPose.cell) && io.dir(m.scanPose.heading))) return false;
    for (auto& r : m.scan) {
      if (!io.part(r)) return false;
    }
    return true;
  }
};
template <>
struct Layout<RoomExitMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.part(m.door) && io.cell(m.inside) && io.dir(m.outward) &&
           io.check([&] { return crossesFrom(m.door, m.outward, m.inside); });
  }
};
template <>
struct Layout<RoomExitsMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    if (!(io.u16(m.roomId) && io.enum8(m.end, ExplorerEnd::ActionLimit) &&
          io.count(m.count, uint8_t{0}, kMaxRoomExits))) {
      return false;
    }
    for (uint8_t i = 0; i < m.count; ++i) {
      if (!io.part(m.exits[i])) return false;
    }
    return true;
  }
};
template <>
struct Layout<NewRoomMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.roomId) && io.cell(m.entry) && io.u16(m.fromRoom) && io.cell(m.origin) && io.dir(m.heading);
  }
};

size_t encodeExplore(const ExploreMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeExplore(const uint8_t* p, size_t n, ExploreMsg& out) { return decodeFields(p, n, out); }
size_t encodeGoTo(const GoToMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeGoTo(const uint8_t* p, size_t n, GoToMsg& out) { return decodeFields(p, n, out); }
size_t encodeEnterRoom(const EnterRoomMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeEnterRoom(const uint8_t* p, size_t n, EnterRoomMsg& out) { return decodeFields(p, n, out); }
size_t encodeScan(const ScanMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeScan(const uint8_t* p, size_t n, ScanMsg& out) { return decodeFields(p, n, out); }
size_t encodeReadings(const ReadingsMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeReadings(const uint8_t* p, size_t n, ReadingsMsg& out) { return decodeFields(p, n, out); }
size_t encodeRoomExits(const RoomExitsMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeRoomExits(const uint8_t* p, size_t n, RoomExitsMsg& out) { return decodeFields(p, n, out); }
size_t encodeNewRoom(const NewRoomMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeNewRoom(const uint8_t* p, size_t n, NewRoomMsg& out) { return decodeFields(p, n, out); }

}  // namespace nxtmap::protocol
