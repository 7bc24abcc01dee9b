#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace nxtmap::fw::test {

// A register-level stand-in for the brick's memory-mapped peripherals: the drivers' Bus
// (read / write / address). Registers hold what was last written unless a hook models them;
// every write is logged in order. address() hands out fake 32-bit bus addresses for buffers a
// driver gives to a PDC, and pointer() turns them back.
class FakeBus {
 public:
  uint32_t read(uint32_t addr) {
    if (onRead) {
      uint32_t v = 0;
      if (onRead(addr, v)) return v;
    }
    auto it = regs.find(addr);
    return it == regs.end() ? 0u : it->second;
  }
  void write(uint32_t addr, uint32_t value) {
    writes.emplace_back(addr, value);
    regs[addr] = value;
    if (onWrite) onWrite(addr, value);
  }
  uint32_t address(const void* p) {
    for (size_t i = 0; i < buffers.size(); ++i)
      if (buffers[i] == p) return kBufferBase + static_cast<uint32_t>(i) * 0x10000u;
    buffers.push_back(p);
    return kBufferBase + static_cast<uint32_t>(buffers.size() - 1) * 0x10000u;
  }
  const uint8_t* pointer(uint32_t busAddress) const {
    const uint32_t i = (busAddress - kBufferBase) / 0x10000u;
    return static_cast<const uint8_t*>(buffers.at(i)) + (busAddress - kBufferBase) % 0x10000u;
  }
  // Values written to one register, in order.
  std::vector<uint32_t> writesTo(uint32_t addr) const {
    std::vector<uint32_t> out;
    for (const auto& w : writes)
      if (w.first == addr) out.push_back(w.second);
    return out;
  }

  std::map<uint32_t, uint32_t> regs;
  std::vector<std::pair<uint32_t, uint32_t>> writes;
  std::function<bool(uint32_t, uint32_t&)> onRead;  // return true to supply the value
  std::function<void(uint32_t, uint32_t)> onWrite;

 private:
  static constexpr uint32_t kBufferBase = 0x20000000u;
  std::vector<const void*> buffers;
};

}  // namespace nxtmap::fw::test
