#pragma once
#include <cstdint>

namespace nxtmap::fw {

// A 3 x 5 pixel font (our own) for the LCD's status lines: digits, capitals and "-:./_".
// Glyph bit (row * 3 + column) is set when the pixel is dark; row 0 at the top, column 0 left.
// Lower-case letters are drawn as capitals; anything else is blank.
class Font3x5 {
 public:
  static constexpr int kWidth = 3, kHeight = 5, kAdvance = 4;
  static uint16_t glyph(char c) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    for (int i = 0; kOrder[i] != 0; ++i) {
      if (kOrder[i] == c) return kGlyphs[i];
    }
    return 0;
  }

 private:
  static constexpr char kOrder[] = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-:./_";
  static constexpr uint16_t kGlyphs[] = {
      0x7B6F, 0x749A, 0x73E7, 0x79A7, 0x49ED, 0x79CF, 0x7BCF, 0x24A7, 0x7BEF, 0x79EF, 0x5BEA, 0x3AEB, 0x624E, 0x3B6B,
      0x72CF, 0x12CF, 0x6B4E, 0x5BED, 0x7497, 0x2B24, 0x5AED, 0x7249, 0x5BFD, 0x5B6B, 0x2B6A, 0x12EB, 0x676A, 0x5AEB,
      0x388E, 0x2497, 0x7B6D, 0x2B6D, 0x5FED, 0x5AAD, 0x24AD, 0x72A7, 0x01C0, 0x0410, 0x2000, 0x12A4, 0x7000,
  };
};

}  // namespace nxtmap::fw
