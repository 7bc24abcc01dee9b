#include "host/sim/PgmImage.hpp"

#include "host/sim/InputFile.hpp"

#include <cctype>

namespace nxtmap::sim {

namespace {

constexpr long kMaxPixelsPerSide = kMaxPgmSide;

// Walks the header: whitespace-separated tokens, '#' comments running to the end of the line.
class HeaderReader {
 public:
  explicit HeaderReader(const std::string& data) : data_(data) {}

  // Next token, or empty at end of data.
  std::string token() {
    while (pos_ < data_.size()) {
      const unsigned char c = static_cast<unsigned char>(data_[pos_]);
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
      } else if (std::isspace(c)) {
        ++pos_;
      } else {
        break;
      }
    }
    const size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_])) && data_[pos_] != '#') {
      ++pos_;
    }
    return data_.substr(start, pos_ - start);
  }

  // Non-negative decimal number, or -1.
  long number() {
    const std::string t = token();
    if (t.empty() || t.size() > 9) return -1;
    long v = 0;
    for (char c : t) {
      if (c < '0' || c > '9') return -1;
      v = v * 10 + (c - '0');
    }
    return v;
  }

  size_t pos() const { return pos_; }

 private:
  const std::string& data_;
  size_t pos_ = 0;
};

}  // namespace

std::optional<PgmImage> readPgm(const std::string& path, std::string& error) {
  const std::optional<std::string> file = readInputFile(path, kMaxPgmBytes, "image file", error);
  if (!file) return std::nullopt;
  const std::string& data = *file;
  HeaderReader header(data);
  const std::string magic = header.token();
  if (magic != "P5" && magic != "P2") {
    error = path + ": not a PGM image (magic '" + magic + "', expected P5 or P2)";
    return std::nullopt;
  }
  const long w = header.number();
  const long h = header.number();
  const long maxval = header.number();
  if (w <= 0 || h <= 0 || w > kMaxPixelsPerSide || h > kMaxPixelsPerSide) {
    error = path + ": bad PGM size (each side must be 1.." + std::to_string(kMaxPixelsPerSide) + ")";
    return std::nullopt;
  }
  if (maxval <= 0 || maxval > 65535) {
    error = path + ": bad PGM maxval (must be 1..65535)";
    return std::nullopt;
  }
  PgmImage img;
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  img.maxval = static_cast<int>(maxval);
  const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h);
  img.pixels.resize(count);
  if (magic == "P5") {
    const size_t bytesPerPixel = maxval < 256 ? 1 : 2;
    const size_t start = header.pos() + 1;  // exactly one whitespace byte after maxval
    if (start > data.size() || data.size() - start < count * bytesPerPixel) {
      error = path + ": PGM pixel data truncated";
      return std::nullopt;
    }
    for (size_t i = 0; i < count; ++i) {
      const size_t at = start + i * bytesPerPixel;
      unsigned v = static_cast<unsigned char>(data[at]);
      if (bytesPerPixel == 2) v = (v << 8) | static_cast<unsigned char>(data[at + 1]);
      img.pixels[i] = static_cast<uint16_t>(v);
    }
  } else {
    for (size_t i = 0; i < count; ++i) {
      const long v = header.number();
      if (v < 0) {
        error = path + ": PGM pixel data truncated or malformed";
        return std::nullopt;
      }
      img.pixels[i] = static_cast<uint16_t>(v > 65535 ? 65535 : v);
    }
  }
  for (uint16_t v : img.pixels) {
    if (v > maxval) {
      error = path + ": PGM pixel value above maxval";
      return std::nullopt;
    }
  }
  return img;
}

}  // namespace nxtmap::sim
