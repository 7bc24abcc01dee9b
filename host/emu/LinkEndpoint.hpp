// LinkEndpoint: the PC side of the emulated Bluetooth link. Byte-transparent: what the firmware sends in
// stream mode comes out here, and what the PC writes goes to the firmware. Implementations: an in-memory
// pipe (tests), a TCP listener on 127.0.0.1 and a pseudo-terminal (LinkServer.hpp).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace nxtmap::emu {

class LinkEndpoint {
 public:
  virtual ~LinkEndpoint() = default;
  // Polls the transport (non-blocking); true if a PC is connected.
  virtual bool connected() = 0;
  virtual void send(const uint8_t* data, size_t n) = 0;
  // Moves up to maxBytes of what the PC sent so far into `out` (appends); the rest stays with the
  // transport, whose flow control then holds the PC back.
  virtual void receive(std::deque<uint8_t>& out, size_t maxBytes) = 0;
  // Blocks up to timeoutMs for PC activity (used while the brick idles with nothing else to do).
  virtual bool waitForActivity(int timeoutMs) = 0;
};

// A PC side held in memory: a test writes toBrick and reads fromBrick.
class MemoryLink : public LinkEndpoint {
 public:
  bool pcConnected = true;
  std::deque<uint8_t> toBrick;
  std::vector<uint8_t> fromBrick;
  bool connected() override { return pcConnected; }
  void send(const uint8_t* d, size_t n) override { fromBrick.insert(fromBrick.end(), d, d + n); }
  void receive(std::deque<uint8_t>& out, size_t maxBytes) override {
    const auto n = static_cast<std::ptrdiff_t>(std::min(maxBytes, toBrick.size()));
    out.insert(out.end(), toBrick.begin(), toBrick.begin() + n);
    toBrick.erase(toBrick.begin(), toBrick.begin() + n);
  }
  bool waitForActivity(int) override { return false; }
};

}  // namespace nxtmap::emu
