// LinkEndpoint: the PC side of the emulated Bluetooth link. Byte-transparent: what the firmware sends in
// stream mode comes out here, and what the PC writes goes to the firmware. Implementations: an in-memory
// pipe (tests), a TCP listener on 127.0.0.1 and a pseudo-terminal (LinkServer.hpp).
#pragma once

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
    // Moves what the PC sent so far into `out` (appends).
    virtual void receive(std::deque<uint8_t>& out) = 0;
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
    void receive(std::deque<uint8_t>& out) override {
        out.insert(out.end(), toBrick.begin(), toBrick.end());
        toBrick.clear();
    }
    bool waitForActivity(int) override { return false; }
};

}  // namespace nxtmap::emu
