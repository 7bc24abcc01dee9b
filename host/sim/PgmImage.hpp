// PgmImage: a grey image read from a binary (P5) or ASCII (P2) portable graymap file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

struct PgmImage {
    int width = 0;                 // pixels, >= 1
    int height = 0;                // pixels, >= 1
    int maxval = 255;              // 1..65535
    std::vector<uint16_t> pixels;  // row-major, row 0 = top of the image, each 0..maxval
};

// Reads the file; on failure returns nullopt and sets error (naming the file and the problem).
std::optional<PgmImage> readPgm(const std::string& path, std::string& error);

}  // namespace nxtmap::sim
