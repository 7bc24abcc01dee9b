#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/protocol/ByteReader.hpp"
#include "common/protocol/ByteWriter.hpp"
#include "common/protocol/Payload.hpp"

// Each message's fields are written once, as Layout<Msg>::fields(io, m): a chain of field
// operations, in wire order, over an "io" that is either a FieldWriter (encode: m is const) or a
// FieldReader (decode: m is filled in). Every operation returns false to stop the chain.
//
//   template <> struct Layout<GoToMsg> {
//     template <class Io, class M> static bool fields(Io& io, M& m) { return io.u16(m.goalId) && io.cell(m.target); }
//   };
//
// Range checks belong to the reader only (an encoder writes what it is given, so tests can build
// malformed payloads), except count(): an array length, checked both ways so neither side runs
// past the array. check(pred) is a reader-only condition over fields read so far; the writer
// never calls pred.
namespace nxtmap::protocol {

template <class Msg>
struct Layout;  // specialised next to each message's codec

constexpr int16_t kCoordLimit = 16384;  // |coordinate| < this for cells on the wire

constexpr bool coordOk(Cell c) {
  return c.x > -kCoordLimit && c.x < kCoordLimit && c.y > -kCoordLimit && c.y < kCoordLimit;
}
// A window on the wire: the canonical empty box, or corners in range and at most max cells each way.
constexpr bool boundsOk(const Bounds& b, int maxWidth, int maxHeight) {
  if (!coordOk(Cell{b.minX, b.minY}) || !coordOk(Cell{b.maxX, b.maxY})) return false;
  if (b.empty()) return b.minX == 0 && b.minY == 0 && b.maxX == -1 && b.maxY == -1;
  return b.width() <= maxWidth && b.height() <= maxHeight;
}

// Encodes fields little-endian into a caller-owned buffer; fails when the buffer is full.
class FieldWriter {
 public:
  FieldWriter(uint8_t* out, size_t capacity) : w_(out, capacity) {}

  bool u8(const uint8_t& v) {
    w_.u8(v);
    return w_.ok();
  }
  bool u16(const uint16_t& v) {
    w_.u16(v);
    return w_.ok();
  }
  bool i16(const int16_t& v) {
    w_.i16(v);
    return w_.ok();
  }
  bool u32(const uint32_t& v) {
    w_.u32(v);
    return w_.ok();
  }
  bool bytes(const uint8_t* v, size_t n) {
    w_.bytes(v, n);
    return w_.ok();
  }
  bool u8In(const uint8_t& v, uint8_t, uint8_t) { return u8(v); }
  bool u16In(const uint16_t& v, uint16_t, uint16_t) { return u16(v); }
  bool i16In(const int16_t& v, int16_t, int16_t) { return i16(v); }
  bool flag(const bool& v) { return u8(v ? 1 : 0); }
  template <class E>
  bool enum8(const E& v, E) {
    return u8(static_cast<uint8_t>(v));
  }
  bool dir(const Dir& v) { return enum8(v, Dir::West); }
  bool cell(const Cell& c) { return i16(c.x) && i16(c.y); }
  bool bounds(const Bounds& b) { return i16(b.minX) && i16(b.minY) && i16(b.maxX) && i16(b.maxY); }
  // Two 4-bit values in one byte, `lo` in the low nibble.
  bool nibbles(const uint8_t& lo, const uint8_t& hi, uint8_t, uint8_t) {
    return u8(static_cast<uint8_t>((lo & 0xFu) | (hi << 4)));
  }
  template <class N>
  bool count(const N& n, N lo, N hi) {
    return n >= lo && n <= hi && put(n);
  }
  template <class Pred>
  bool check(Pred&&) {
    return true;
  }
  template <class T>
  bool part(const T& v) {
    return Layout<T>::fields(*this, v);
  }

  size_t size() const { return w_.size(); }

 private:
  bool put(const uint8_t& v) { return u8(v); }
  bool put(const uint16_t& v) { return u16(v); }

  ByteWriter w_;
};

// Decodes fields and checks every range; a short read fails.
class FieldReader {
 public:
  FieldReader(const uint8_t* p, size_t n) : r_(p, n) {}

  bool u8(uint8_t& v) {
    v = r_.u8();
    return r_.ok();
  }
  bool u16(uint16_t& v) {
    v = r_.u16();
    return r_.ok();
  }
  bool i16(int16_t& v) {
    v = r_.i16();
    return r_.ok();
  }
  bool u32(uint32_t& v) {
    v = r_.u32();
    return r_.ok();
  }
  bool bytes(uint8_t* v, size_t n) {
    r_.bytes(v, n);
    return r_.ok();
  }
  bool u8In(uint8_t& v, uint8_t lo, uint8_t hi) { return u8(v) && v >= lo && v <= hi; }
  bool u16In(uint16_t& v, uint16_t lo, uint16_t hi) { return u16(v) && v >= lo && v <= hi; }
  bool i16In(int16_t& v, int16_t lo, int16_t hi) { return i16(v) && v >= lo && v <= hi; }
  // A byte 0 or 1.
  bool flag(bool& v) {
    uint8_t b = 0;
    if (!u8In(b, 0, 1)) return false;
    v = b == 1;
    return true;
  }
  // A byte 0..last.
  template <class E>
  bool enum8(E& v, E last) {
    uint8_t b = 0;
    if (!u8In(b, 0, static_cast<uint8_t>(last))) return false;
    v = static_cast<E>(b);
    return true;
  }
  bool dir(Dir& v) { return enum8(v, Dir::West); }
  bool cell(Cell& c) { return i16(c.x) && i16(c.y) && coordOk(c); }
  // Corners only: the message checks the window (boundsOk) against its own limits.
  bool bounds(Bounds& b) { return i16(b.minX) && i16(b.minY) && i16(b.maxX) && i16(b.maxY); }
  bool nibbles(uint8_t& lo, uint8_t& hi, uint8_t min, uint8_t max) {
    uint8_t b = 0;
    if (!u8(b)) return false;
    lo = b & 0xFu;
    hi = static_cast<uint8_t>(b >> 4);
    return lo >= min && lo <= max && hi >= min && hi <= max;
  }
  template <class N>
  bool count(N& n, N lo, N hi) {
    return get(n) && n >= lo && n <= hi;
  }
  template <class Pred>
  bool check(Pred&& pred) {
    return pred();
  }
  template <class T>
  bool part(T& v) {
    return Layout<T>::fields(*this, v);
  }

  bool atEnd() const { return r_.atEnd(); }

 private:
  bool get(uint8_t& v) { return u8(v); }
  bool get(uint16_t& v) { return u16(v); }

  ByteReader r_;
};

// encodeX / decodeX of a message with a Layout.
template <class Msg>
size_t encodeFields(const Msg& m, Payload& out) {
  FieldWriter w(out.bytes, sizeof(out.bytes));
  out.size = Layout<Msg>::fields(w, m) ? w.size() : 0;
  return out.size;
}
// Refuses anything Layout<Msg> refuses, and trailing bytes. `out` is unspecified on failure.
template <class Msg>
bool decodeFields(const uint8_t* p, size_t n, Msg& out) {
  out = Msg{};
  FieldReader r(p, n);
  return Layout<Msg>::fields(r, out) && r.atEnd();
}

}  // namespace nxtmap::protocol
