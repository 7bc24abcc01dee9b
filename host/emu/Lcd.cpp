#include "host/emu/Lcd.hpp"

#include <vector>

#include "host/fileio/PngFile.hpp"

namespace nxtmap::emu {

void Lcd::byte(bool data, uint8_t v) {
  if (data) {
    if (page_ < kPages && column_ < kColumns) ram_[static_cast<size_t>(page_)][static_cast<size_t>(column_)] = v;
    column_ = (column_ + 1) % kColumns;  // auto-wrap (RAM address control 0x89)
    ++dataBytes_;
    return;
  }
  ++commandBytes_;
  if (expectArg_) {
    expectArg_ = false;
    return;
  }
  if (!command(v) && fault_.empty()) {
    static const char* const kHex = "0123456789ABCDEF";
    fault_ = std::string("unknown UC1601 command 0x") + kHex[v >> 4] + kHex[v & 15];
    if (onFault_) onFault_(fault_);
  }
}

// The UC1601 command set (datasheet command table); two-byte commands take the next byte as argument.
bool Lcd::command(uint8_t v) {
  if (v <= 0x0F) {
    column_ = (column_ & 0xF0) | v;  // column address LSB
  } else if (v <= 0x1F) {
    column_ = (column_ & 0x0F) | ((v & 0x0F) << 4);  // column address MSB
  } else if (v <= 0x2F) {
    // 0x20-0x23 multiplex rate, 0x24-0x27 temperature compensation, 0x28-0x2F power control
  } else if (v == 0x30 || v == 0x31) {
    expectArg_ = true;  // advanced program control
  } else if (v <= 0x3F) {
    return false;
  } else if (v <= 0x7F) {
    // scroll line
  } else if (v == 0x81) {
    expectArg_ = true;  // VBIAS potentiometer (contrast)
  } else if (v == 0x84 || v == 0x85 || (v >= 0x88 && v <= 0xA3)) {
    // partial display, RAM address control, fixed lines, line rate
  } else if (v == 0xA4 || v == 0xA5) {
    allOn_ = v & 1;
  } else if (v == 0xA6 || v == 0xA7) {
    inverse_ = v & 1;
  } else if (v == 0xAE || v == 0xAF) {
    on_ = v & 1;
  } else if (v >= 0xB0 && v <= 0xB8) {
    page_ = v & 0x0F;  // page 8 is the icon row: not shown
  } else if (v >= 0xC0 && v <= 0xC7) {
    // LCD mapping control
  } else if (v == 0xC8 || v == 0xF1 || v == 0xF2 || v == 0xF3 || (v >= 0xF4 && v <= 0xF7)) {
    expectArg_ = true;  // N-line inversion, COM end, partial display start/end, window
  } else if (v >= 0xE8 && v <= 0xEB) {
    // bias ratio
  } else if (v == 0xE2) {
    on_ = allOn_ = inverse_ = false;  // system reset
    column_ = 0;
    page_ = 0;
  } else if (v == 0xE3 || v == 0xF8 || v == 0xF9) {
    // NOP, window program mode
  } else {
    return false;
  }
  return true;
}

bool Lcd::pixel(int x, int y) const {
  if (x < 0 || x >= kWidth || y < 0 || y >= kHeight || !on_) return false;
  if (allOn_) return true;
  const bool set = (ram_[static_cast<size_t>(y / 8)][static_cast<size_t>(x)] >> (y % 8)) & 1u;
  return set != inverse_;
}

bool Lcd::savePng(const std::string& path, int scale, std::string& error) const {
  // 8-bit grey, encoded in memory (scale 1..16: at most 1600 x 1024 bytes raw), then written whole
  // or not at all: a failed write leaves `path` as it was.
  if (scale < 1 || scale > 16) {
    error = "cannot write " + path + ": LCD scale must lie in 1..16";
    return false;
  }
  const int w = kWidth * scale, h = kHeight * scale;
  std::vector<uint8_t> grey(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      grey[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] =
          pixel(x / scale, y / scale) ? 0x20 : 0xC8;
    }
  }
  return fileio::writePngFile(path, w, h, 1, grey.data(), error);
}

}  // namespace nxtmap::emu
