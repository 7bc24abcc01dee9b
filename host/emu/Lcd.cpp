#include "host/emu/Lcd.hpp"

#include <png.h>

#include <cstdio>
#include <vector>

namespace nxtmap::emu {

void Lcd::byte(bool data, uint8_t v) {
    if (data) {
        if (page_ < kPages && column_ < kColumns) ram_[static_cast<size_t>(page_)][static_cast<size_t>(column_)] = v;
        column_ = (column_ + 1) % kColumns;  // auto-wrap (RAM address control 0x89)
        ++dataBytes_;
        return;
    }
    if (expectArg_) { expectArg_ = false; return; }
    if (v <= 0x0F) column_ = (column_ & 0xF0) | v;
    else if (v <= 0x1F) column_ = (column_ & 0x0F) | ((v & 0x0F) << 4);
    else if ((v & 0xF0) == 0xB0) page_ = v & 0x0F;
    else if (v == 0xAF) on_ = true;
    else if (v == 0xAE) on_ = false;
    else if (v == 0x81) expectArg_ = true;  // contrast: one argument byte
    else if (v == 0xE2) { on_ = false; column_ = 0; page_ = 0; }
}

bool Lcd::pixel(int x, int y) const {
    if (x < 0 || x >= kWidth || y < 0 || y >= kHeight) return false;
    return (ram_[static_cast<size_t>(y / 8)][static_cast<size_t>(x)] >> (y % 8)) & 1u;
}

bool Lcd::savePng(const std::string& path, int scale, std::string& error) const {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) { error = "cannot write " + path; return false; }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        error = "PNG encoding failed for " + path;
        return false;
    }
    const int w = kWidth * scale, h = kHeight * scale;
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    std::vector<png_byte> row(static_cast<size_t>(w));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) row[static_cast<size_t>(x)] = pixel(x / scale, y / scale) ? 0x20 : 0xC8;
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return true;
}

}  // namespace nxtmap::emu
