#include "host/report/TerminalText.hpp"

#include <cstddef>
#include <cstdint>

namespace nxtmap::report {
namespace {

void appendHex(std::string& out, uint8_t byte) {
  static const char kDigits[] = "0123456789abcdef";
  out += "\\x";
  out += kDigits[byte >> 4];
  out += kDigits[byte & 0x0f];
}

// Length of the well-formed UTF-8 sequence starting at text[i] (2-4 bytes, no overlongs, no surrogates,
// at most U+10FFFF), or 0 when the bytes there are not one.
size_t utf8SequenceLength(const std::string& text, size_t i) {
  const auto at = [&](size_t k) { return static_cast<uint8_t>(text[k]); };
  const uint8_t lead = at(i);
  size_t n = 0;
  uint8_t lo = 0x80, hi = 0xbf;  // the allowed range of the second byte
  if (lead >= 0xc2 && lead <= 0xdf)
    n = 2;
  else if (lead == 0xe0)
    n = 3, lo = 0xa0;
  else if (lead >= 0xe1 && lead <= 0xec)
    n = 3;
  else if (lead == 0xed)
    n = 3, hi = 0x9f;
  else if (lead >= 0xee && lead <= 0xef)
    n = 3;
  else if (lead == 0xf0)
    n = 4, lo = 0x90;
  else if (lead >= 0xf1 && lead <= 0xf3)
    n = 4;
  else if (lead == 0xf4)
    n = 4, hi = 0x8f;
  else
    return 0;
  if (i + n > text.size()) return 0;
  if (at(i + 1) < lo || at(i + 1) > hi) return 0;
  for (size_t k = 2; k < n; ++k) {
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  }
  return n;
}

}  // namespace

std::string escapeForTerminal(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<uint8_t>(text[i]);
    if (byte == '\n' || byte == '\r') {
      out += ' ';
      ++i;
    } else if (byte < 0x20 || byte == 0x7f) {
      appendHex(out, byte);
      ++i;
    } else if (byte < 0x80) {
      out += text[i++];
    } else if (const size_t n = utf8SequenceLength(text, i); n == 0) {
      appendHex(out, byte);
      ++i;
    } else if (byte == 0xc2 && static_cast<uint8_t>(text[i + 1]) <= 0x9f) {  // a C1 control
      appendHex(out, byte);
      appendHex(out, static_cast<uint8_t>(text[i + 1]));
      i += 2;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

}  // namespace nxtmap::report
