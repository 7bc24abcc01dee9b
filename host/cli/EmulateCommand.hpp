// `nxtmap emulate WORLD --start C,R [--firmware FILE.elf|FILE.bin] [--listen tcp:127.0.0.1:PORT|pty] [--lcd FILE.png
//  [--lcd-every SECONDS]] [--speed max|realtime] [--noise P] [--seed N] [--flash-keep FILE]`: the real firmware image, instruction by instruction, in
// the emulated brick driving the simulated robot; the PC console connects to the listening end as it would
// to a brick over Bluetooth. Prints the run's measurements at the end.
#pragma once
#include <string>

#include "host/cli/SiteFiles.hpp"

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct EmulateOptions {
  std::string world;
  std::string start;
  std::string heading = "N";
  std::string firmware = "build/firmware/nxtmap.elf";
  std::string listen;                     // empty = no PC side
  std::string until;                      // explored | disconnect (default: disconnect with --listen, else explored)
  std::string lcd;                        // PNG of the LCD at the end
  std::string png;                        // with score: PNG of the radio map laid on the world
  double lcdEvery = 0.0;                  // > 0: also numbered PNGs beside it every this many emulated seconds
  std::string speed = "max";              // max | realtime
  WorldRunOptions run{"ideal", "", 0.0};  // --noise, --robot (empty: the firmware's own), --start-jitter
  std::string seed = "1";
  double seconds = 3600.0;  // emulated time limit
  double enterAt = 1.0;     // emulated second at which Enter is pressed (< 0: never)
  bool profile = false;     // print where the costliest sensor update's instructions went
  bool score = false;       // a PC on the radio keeps the brick's map; scored against the world at the end
  std::string flashKeep;    // the brick's flash kept in this file from run to run (FlashState); empty: none
};

CLI::App* addEmulateCommand(CLI::App& app, EmulateOptions& options);
int runEmulate(const EmulateOptions& options);

}  // namespace nxtmap::cli
