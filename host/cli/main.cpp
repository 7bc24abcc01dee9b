// nxtmap: the console program; everything lives in the nxtmap_cli library.
#include "host/cli/App.hpp"

int main(int argc, char** argv) { return nxtmap::cli::runCli(argc, argv); }
