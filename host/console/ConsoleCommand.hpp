// ConsoleCommand: one line typed at `nxtmap connect`, parsed and checked before anything is sent.
#pragma once
#include <stdexcept>
#include <string>

namespace nxtmap::console {

struct ConsoleCommand {
  enum class Kind {
    Explore,
    ExploreHouse,
    Stop,
    Calibrate,
    Goto,
    GotoNear,
    Label,
    Rooms,
    Route,
    Save,
    Export,
    Status,
    Battery,
    Map,
    Wait,
    Help,
    Quit,
    Empty
  };
  Kind kind = Kind::Empty;
  int col = 0, row = 0;  // Goto, Label, Route: map cell (column right, row down, as the map display shows)
  std::string name;      // Label, GotoNear: label; Route: room (or label with near); Save: file or house
                         // directory; Export: file; Wait: what
  bool near = false;     // Route: `route near LABEL`
  double seconds = 0;    // Wait, Calibrate: the longest wait
};

// A malformed line: the message names what was wrong and the right form.
class ConsoleError : public std::runtime_error {
 public:
  explicit ConsoleError(const std::string& m) : std::runtime_error(m) {}
};

// Parses one line; throws ConsoleError.
ConsoleCommand parseConsoleCommand(const std::string& line);

// The help text (one command per line).
const char* consoleHelp();

}  // namespace nxtmap::console
