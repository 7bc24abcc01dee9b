// `nxtmap path --house DIR --from ROOM:C,R --to ROOM:C,R|near:LABEL [--algo A]`: a route across the
// rooms of a saved house (network::planHouseRoute): the rooms passed and the path in each room.
// C,R are cells of the room's map (col right, row down in its PGM), as `nxtmap path` uses them.
#pragma once

#include "host/cli/PathCommand.hpp"

namespace nxtmap::cli {

// Throws CliError on bad input (including no route); returns the exit code.
int runHousePath(const PathOptions& options);

}  // namespace nxtmap::cli
