// Lcd: the UC1601 display controller (100x64 visible of 132 columns x 8 pages) on SPI. A0 (PA12) low =
// command, high = data. Strict: the panel shows nothing (every pixel clear) until the display is enabled
// (0xAF) and after a system reset (0xE2) until enabled again; all-pixels-on (0xA5) and inverse (0xA7)
// change what it shows. Every command byte must be one of the UC1601's commands (the table in Lcd.cpp:
// column/page address, temperature compensation, power control, scroll line, VBIAS potentiometer + its
// argument, RAM address control, line rate, mapping, bias ratio, reset, NOP, ...); any other byte is a
// fault (fault() names the first one, and the fault handler, when set, is told at once: the brick stops
// the machine with it). Data bytes land at [page][column], column auto-increments. The
// picture can be saved as PNG (1 = dark pixel; bit n = row 8*page+n).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

namespace nxtmap::emu {

class Lcd {
 public:
  static constexpr int kWidth = 100, kHeight = 64, kColumns = 132, kPages = 8;
  void byte(bool data, uint8_t value);
  bool pixel(int x, int y) const;  // x 0..99, y 0..63
  bool displayOn() const { return on_; }
  // Empty, or the first command byte the UC1601 does not know ("unknown UC1601 command 0x..").
  const std::string& fault() const { return fault_; }
  // Called once, with the fault's text, when the first fault happens.
  void onFault(std::function<void(const std::string&)> handler) { onFault_ = std::move(handler); }
  uint64_t commandBytes() const { return commandBytes_; }
  uint64_t dataBytes() const { return dataBytes_; }
  // Writes a PNG (scale x scale pixels per LCD pixel, scale 1..16) whole or not at all (fileio::AtomicFile);
  // false with the path and the reason in error, `path` then untouched.
  bool savePng(const std::string& path, int scale, std::string& error) const;

 private:
  std::array<std::array<uint8_t, kColumns>, kPages> ram_{};
  int column_ = 0, page_ = 0;
  bool command(uint8_t v);  // false: not a UC1601 command
  bool on_ = false, allOn_ = false, inverse_ = false;
  bool expectArg_ = false;  // the next command byte is an argument (e.g. after 0x81 contrast)
  uint64_t dataBytes_ = 0, commandBytes_ = 0;
  std::string fault_;
  std::function<void(const std::string&)> onFault_;
};

}  // namespace nxtmap::emu
