#pragma once
#include <cstddef>
#include <cstdint>

namespace nxtmap::protocol {

// CRC-32 (IEEE 802.3, polynomial 0xEDB88320 reflected, init and final xor 0xFFFFFFFF; the same
// value as zlib's crc32). Nibble-table implementation: 64 bytes of table, ~8 operations per byte.
uint32_t crc32(const uint8_t* data, size_t size);

}  // namespace nxtmap::protocol
