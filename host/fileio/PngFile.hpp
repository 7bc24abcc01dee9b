// PngFile: a picture written as PNG whole or not at all: encoded in memory (libpng's simplified API), then
// written through AtomicFile, so a failed write leaves the target as it was and says why.
#pragma once

#include <cstdint>
#include <string>

namespace nxtmap::fileio {

// `pixels`: width x height samples, row-major, `channels` bytes each (1: grey, 3: RGB). False with `error`
// ("cannot write PATH: <reason>") on an empty picture, a failed encoding or a failed write.
bool writePngFile(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                  std::string& error);

}  // namespace nxtmap::fileio
