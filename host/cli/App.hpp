// App: the `nxtmap` console: parses the command line and dispatches to one command.
#pragma once

namespace nxtmap::cli {

// The whole program; returns the exit code (0 ok, 2 bad input).
int runCli(int argc, char** argv);

}  // namespace nxtmap::cli
