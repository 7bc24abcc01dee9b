// The radio link's figures for `make bench`: bytes on the wire per cell change at 460800 baud
// and the lag from a change of the brick's grid to the PC's copy, on a clean link and with 5 %
// damaged bytes (the stand-in brick and the PC session on the link harness's virtual clock).
#pragma once
#include <string>

namespace nxtmap::bench {

// Prints the link section; `world` is a Moving AI map, started at (col, row).
void printLinkBench(const std::string& world, int col, int row);

}  // namespace nxtmap::bench
