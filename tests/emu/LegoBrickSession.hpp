// LegoBrickSession: a PC tool speaking LEGO's commands (LegoClient) to the real firmware image in the emulated
// brick, over the emulated Bluetooth link, stepped with the emulated clock. A script is a list of requests; a
// request marked withPrevious goes out in the same burst as the one before it (back to back, without waiting
// for that one's reply); every other request waits until the replies asked for so far have arrived (or timed
// out). Replies are paired with requests in order, as LEGO's protocol has no request number: a lost or extra
// reply shows as a mismatched opcode from there on. Times are emulated milliseconds.
#pragma once

#include "LegoClient.hpp"

#include <string>
#include <vector>

namespace nxtmap::emu::lego {

struct Step {
  Bytes request;
  bool withPrevious = false;
};

struct Exchange {
  Bytes request;
  Reply reply;                // empty if none came (or none was asked for)
  bool answered = false;      // a reply arrived within the time-out
  double sentMs = 0;          // when the request entered the PC's side of the link
  double repliedMs = 0;       // when its reply was whole on the PC's side
  double drivenCmAtSend = 0;  // the robot's driven distance then (cm), to tell exchanges while driving
  double drivenCmAtReply = 0;
  double motorADegAtSend = 0;  // motor A's encoder in the emulated drive (degrees, signed)
  double motorADegAtReply = 0;
  double roundTripMs() const { return repliedMs - sentMs; }
  bool whileDriving() const { return drivenCmAtReply > drivenCmAtSend; }
};

struct SessionOptions {
  std::string firmware;          // the ELF image; empty: nxtmap-sim.elf of the test build
  bool drive = false;            // press Enter at 1 s: the robot explores while the script runs
  double startAtS = 0.5;         // first request (emulated s), once the stream is open
  double gapMs = 0;              // pause after each answered group before the next
  double replyTimeoutMs = 1500;  // a reply later than this counts as missing
  double maxSeconds = 120;       // emulated limit of the whole session
};

struct SessionResult {
  std::string error;  // the image did not load, a fault, or the stream never opened
  std::vector<Exchange> exchanges;
  std::vector<Bytes> otherTelegrams;  // telegrams from the brick that were not LEGO replies
  size_t extraReplies = 0;            // replies with no request waiting for one
  size_t packets = 0;                 // radio packets (the BlueCore's bursts) the PC received
  size_t cutTelegrams = 0;            // telegrams split across two packets (a PC's single read gets part)
  double endS = 0;
};

// Runs the script against the firmware in the emulated brick (world: occupancy-120, as the link tests use).
SessionResult runSession(const std::vector<Step>& script, const SessionOptions& options);

// The default image: $NXTMAP_FIRMWARE if set, else nxtmap-sim.elf of the test build ("" when it has none).
std::string simFirmwarePath();

}  // namespace nxtmap::emu::lego
