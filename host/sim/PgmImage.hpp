// PgmImage: a grey image read from a binary (P5) or ASCII (P2) portable graymap file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

constexpr int kMaxPgmSide = 4096;  // pixels, the largest width or height read (World::kMaxSide)
// Largest file read, bytes, checked before reading: the largest image as ASCII P2 with every pixel "65535"
// and one separator (96 MiB), with 4 MiB to spare for the header and comments. (As P5 it is 16 or 32 MiB.)
constexpr size_t kMaxPgmBytes = size_t{100} << 20;

struct PgmImage {
  int width = 0;                 // pixels, >= 1
  int height = 0;                // pixels, >= 1
  int maxval = 255;              // 1..65535
  std::vector<uint16_t> pixels;  // row-major, row 0 = top of the image, each 0..maxval
};

// Reads the file (a regular file of at most kMaxPgmBytes); on failure returns nullopt and sets error (naming
// the file and the problem).
std::optional<PgmImage> readPgm(const std::string& path, std::string& error);

}  // namespace nxtmap::sim
