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
  if (expectArg_) {
    expectArg_ = false;
    return;
  }
  if (v <= 0x0F)
    column_ = (column_ & 0xF0) | v;
  else if (v <= 0x1F)
    column_ = (column_ & 0x0F) | ((v & 0x0F) << 4);
  else if ((v & 0xF0) == 0xB0)
    page_ = v & 0x0F;
  else if (v == 0xAF)
    on_ = true;
  else if (v == 0xAE)
    on_ = false;
  else if (v == 0x81)
    expectArg_ = true;  // contrast: one argument byte
  else if (v == 0xE2) {
    on_ = false;
    column_ = 0;
    page_ = 0;
  }
}

bool Lcd::pixel(int x, int y) const {
  if (x < 0 || x >= kWidth || y < 0 || y >= kHeight) return false;
  return (ram_[static_cast<size_t>(y / 8)][static_cast<size_t>(x)] >> (y % 8)) & 1u;
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
