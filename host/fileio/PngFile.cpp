#include "host/fileio/PngFile.hpp"

#include <png.h>
#include <stdio.h>

#include <cstdlib>
#include <cstring>
#include <memory>

#include "host/fileio/AtomicFile.hpp"

namespace nxtmap::fileio {

bool writePngFile(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                  std::string& error) {
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3)) {
    error = "cannot write " + path + ": empty image";
    return false;
  }
  // Encoded in memory first (at most about the size of the raw picture the caller holds).
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(width);
  png.height = static_cast<png_uint_32>(height);
  png.format = channels == 1 ? PNG_FORMAT_GRAY : PNG_FORMAT_RGB;
  char* bytes = nullptr;
  size_t size = 0;
  FILE* memory = open_memstream(&bytes, &size);
  const bool encoded = memory && png_image_write_to_stdio(&png, memory, 0, pixels, 0, nullptr) != 0;
  if (memory) std::fclose(memory);
  std::unique_ptr<char, decltype(&std::free)> owned(bytes, &std::free);
  const std::string why = memory ? png.message : "out of memory";
  png_image_free(&png);
  if (!encoded) {
    error = "cannot write " + path + ": " + why;
    return false;
  }
  AtomicFile out;
  return out.open(path, error) && out.write(bytes, size, error) && out.commit(error);
}

}  // namespace nxtmap::fileio
