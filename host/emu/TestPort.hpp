// TestPort: a test-only device in a reserved hole of the SAM7S map (0xFFFE8000), never present on the
// brick or in `nxtmap emulate`. Probe programs print characters, report values and their exit code here.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <optional>
#include <string>
#include <vector>

namespace nxtmap::emu {

class TestPort : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFE8000;
  static constexpr uint32_t kSize = 0x100;
  const char* name() const override { return "TESTPORT"; }
  bool writeReplans(uint32_t off) const override { return off == 0x10; }  // DONE: stop and look
  bool read(uint32_t off, uint32_t& v) override {
    if (off != 0x00) return false;
    v = 0;
    return true;
  }
  bool write(uint32_t off, uint32_t v) override {
    switch (off) {
      case 0x00: text += static_cast<char>(v & 0xFF); return true;
      case 0x04: values.push_back(v); return true;
      case 0x10: exitCode = static_cast<int>(v); return true;
      default: return false;
    }
  }
  std::string text;
  std::vector<uint32_t> values;
  std::optional<int> exitCode;
};

}  // namespace nxtmap::emu
