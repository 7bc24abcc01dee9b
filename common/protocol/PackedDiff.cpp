#include "common/protocol/PackedDiff.hpp"

namespace nxtmap::protocol {
namespace {
// A 32-bit load that may alias the byte arrays (the callers' storage is uint8_t).
typedef uint32_t __attribute__((may_alias)) AliasWord;

constexpr uintptr_t kWordMask = sizeof(uint32_t) - 1;
}  // namespace

size_t firstDifference(const uint8_t* a, const uint8_t* b, size_t from, size_t end) {
  size_t i = from;
  const bool together = ((reinterpret_cast<uintptr_t>(a) ^ reinterpret_cast<uintptr_t>(b)) & kWordMask) == 0;
  if (together) {
    while (i < end && (reinterpret_cast<uintptr_t>(a + i) & kWordMask) != 0) {
      if (a[i] != b[i]) return i;
      ++i;
    }
    // Aligned words, four at a time (16 bytes per loop test), then one at a time.
    while (i + 16 <= end) {
      const AliasWord* wa = reinterpret_cast<const AliasWord*>(a + i);
      const AliasWord* wb = reinterpret_cast<const AliasWord*>(b + i);
      if (((wa[0] ^ wb[0]) | (wa[1] ^ wb[1]) | (wa[2] ^ wb[2]) | (wa[3] ^ wb[3])) != 0) break;
      i += 16;
    }
    while (i + 4 <= end) {
      if (*reinterpret_cast<const AliasWord*>(a + i) != *reinterpret_cast<const AliasWord*>(b + i)) break;
      i += 4;
    }
  }
  while (i < end && a[i] == b[i]) ++i;
  return i;
}

void extractCells(const uint8_t* torus, uint32_t first, uint32_t count, uint8_t* out) {
  if (count == 0) return;
  const uint32_t skip = first & 3u;  // cells of the first byte before `first`
  const uint32_t shift = skip * 2u;
  const uint8_t* src = torus + (first >> 2);
  const uint32_t n = (count + 3u) / 4u;
  for (uint32_t m = 0; m < n; ++m) {
    uint32_t v = static_cast<uint32_t>(src[m]) >> shift;
    // Output byte m takes cells 4m + 4 - skip .. 4m + 3 from the next source byte.
    if (skip != 0 && 4u * m + 4u - skip < count) v |= static_cast<uint32_t>(src[m + 1]) << (8u - shift);
    out[m] = static_cast<uint8_t>(v);
  }
  const uint32_t tail = count & 3u;
  if (tail != 0) out[n - 1] = static_cast<uint8_t>(out[n - 1] & ((1u << (2u * tail)) - 1u));
}

namespace {
// Writes `from` (a whole torus, or one repeated byte when `step` is 0) into cells [first, first + count) of `to`.
void blendCells(const uint8_t* from, size_t step, uint8_t* to, uint32_t first, uint32_t count) {
  if (count == 0) return;
  const uint32_t last = first + count - 1;
  const uint32_t b0 = first >> 2, b1 = last >> 2;
  const uint8_t head = static_cast<uint8_t>(0xFFu << ((first & 3u) * 2u));        // cells >= first in byte b0
  const uint8_t tail = static_cast<uint8_t>(0xFFu >> ((3u - (last & 3u)) * 2u));  // cells <= last in byte b1
  if (b0 == b1) {
    const uint8_t m = static_cast<uint8_t>(head & tail);
    to[b0] = static_cast<uint8_t>((to[b0] & ~m) | (from[b0 * step] & m));
    return;
  }
  to[b0] = static_cast<uint8_t>((to[b0] & ~head) | (from[b0 * step] & head));
  for (uint32_t b = b0 + 1; b < b1; ++b) to[b] = from[b * step];
  to[b1] = static_cast<uint8_t>((to[b1] & ~tail) | (from[b1 * step] & tail));
}
}  // namespace

void copyCells(const uint8_t* from, uint8_t* to, uint32_t first, uint32_t count) {
  blendCells(from, 1, to, first, count);
}

void setCells(uint8_t* torus, uint32_t first, uint32_t count, uint8_t value) {
  const uint8_t v = static_cast<uint8_t>(value & 3u);
  const uint8_t pattern = static_cast<uint8_t>(v | (v << 2) | (v << 4) | (v << 6));
  blendCells(&pattern, 0, torus, first, count);
}

}  // namespace nxtmap::protocol
