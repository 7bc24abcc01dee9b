#pragma once
#include <cstddef>
#include <cstdint>

namespace nxtmap::protocol {

// Finding where two packed tori of 2-bit cells differ (MapSync: the grid against the shadow of
// what the PC was sent) without decoding cell by cell: whole words while both pointers share
// their alignment, bytes otherwise; only a differing byte is looked into.

// Index of the first byte in [from, end) where `a` and `b` differ, or `end` when none does.
// Compares 4 bytes per step when a + from and b + from have the same alignment (mod 4).
size_t firstDifference(const uint8_t* a, const uint8_t* b, size_t from, size_t end);

// The cells (bit k = cell k of the byte, 0..3, lowest bits first) whose 2-bit values differ
// between bytes `a` and `b`; 0 when the bytes are equal.
constexpr uint8_t differingCells(uint8_t a, uint8_t b) {
  const uint8_t x = static_cast<uint8_t>(a ^ b);
  const uint8_t any = static_cast<uint8_t>((x | (x >> 1)) & 0x55u);  // bit 2k set when cell k differs
  return static_cast<uint8_t>((any & 1u) | ((any >> 1) & 2u) | ((any >> 2) & 4u) | ((any >> 3) & 8u));
}

// The lowest cell in a non-zero differingCells() mask (0..3).
constexpr uint8_t lowestCell(uint8_t mask) { return (mask & 1u) ? 0 : (mask & 2u) ? 1 : (mask & 4u) ? 2 : 3; }

// Whether cell `index` differs between tori `a` and `b` (2 bits per cell).
inline bool cellDiffers(const uint8_t* a, const uint8_t* b, uint32_t index) {
  return (((a[index >> 2] ^ b[index >> 2]) >> ((index & 3u) * 2u)) & 3u) != 0;
}

// Packs cells [first, first + count) of `torus` into `out` as a delta run carries them (cell k
// at bits 2(k%4) of byte k/4; ceil(count/4) bytes, unused high bits zero). Reads no byte past
// the last cell.
void extractCells(const uint8_t* torus, uint32_t first, uint32_t count, uint8_t* out);

// Copies cells [first, first + count) from torus `from` to torus `to`; other cells unchanged.
void copyCells(const uint8_t* from, uint8_t* to, uint32_t first, uint32_t count);

// Sets cells [first, first + count) of `torus` to `value` (0..3); other cells unchanged.
void setCells(uint8_t* torus, uint32_t first, uint32_t count, uint8_t value);

}  // namespace nxtmap::protocol
