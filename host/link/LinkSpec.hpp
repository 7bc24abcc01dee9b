// LinkSpec: how the console reaches a brick, parsed from the LINK argument:
//   bt:00:16:53:AA:BB:CC   Bluetooth RFCOMM channel 1 (BlueZ), the NXT's serial port profile
//   serial:/dev/rfcomm0    a serial device or pty (raw, 460800 baud where the device has a baud rate)
//   tcp:HOST:PORT          TCP, e.g. the emulated brick's radio
//   sim:WORLD[@COL,ROW]    the in-process stand-in brick on a simulator world (tests, demos)
#pragma once
#include <stdexcept>
#include <string>

namespace nxtmap::link {

struct LinkSpec {
  enum class Kind { Bluetooth, Serial, Tcp, Sim };
  Kind kind = Kind::Tcp;
  std::string address;     // bt: "00:16:53:AA:BB:CC"; serial: device path; tcp: host; sim: world file
  int port = 0;            // tcp: 1..65535; bt: RFCOMM channel (1)
  int col = -1, row = -1;  // sim: start cell (-1: the world's default)
  std::string text;        // as given
};

// Bad LINK text: the message says what was wrong and what is accepted.
class LinkError : public std::runtime_error {
 public:
  explicit LinkError(const std::string& m) : std::runtime_error(m) {}
};

// Parses LINK; throws LinkError.
LinkSpec parseLinkSpec(const std::string& text);

}  // namespace nxtmap::link
