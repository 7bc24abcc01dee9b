#include "common/protocol/HouseMessages.hpp"

#include "common/protocol/FieldIo.hpp"

namespace nxtmap::protocol {
namespace {

// `outward` crosses the doorway and one step from `inside` enters it.
bool crossesFrom(const DoorwayMsg& door, Dir outward, Cell inside) {
  return isVertical(outward) == door.alongX && door.contains(advance(inside, outward));
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
size_t encodeRoomExits(const RoomExitsMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeRoomExits(const uint8_t* p, size_t n, RoomExitsMsg& out) { return decodeFields(p, n, out); }
size_t encodeNewRoom(const NewRoomMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeNewRoom(const uint8_t* p, size_t n, NewRoomMsg& out) { return decodeFields(p, n, out); }

}  // namespace nxtmap::protocol
