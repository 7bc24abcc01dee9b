#pragma once
#include <cstdint>

namespace nxtmap {

// The method's three cell states. Stored in 2 bits per cell.
enum class CellState : uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

}  // namespace nxtmap
