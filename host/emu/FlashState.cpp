#include "host/emu/FlashState.hpp"

#include <cstdio>
#include <filesystem>

#include "common/motion/WheelRecord.hpp"
#include "host/emu/ElfImage.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/sim/InputFile.hpp"

namespace nxtmap::emu {

std::optional<std::vector<uint8_t>> readFlashState(const std::string& path, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return std::nullopt;
  const std::optional<std::string> bytes = sim::readInputFile(path, kFlashSize, "flash state file", error);
  if (!bytes) return std::nullopt;
  if (bytes->size() != kFlashSize) {
    error = path + ": not a kept flash (" + std::to_string(bytes->size()) + " bytes, " + std::to_string(kFlashSize) +
            " expected)";
    return std::nullopt;
  }
  return std::vector<uint8_t>(bytes->begin(), bytes->end());
}

bool writeFlashState(const std::string& path, const std::vector<uint8_t>& flash, std::string& error) {
  return fileio::writeFileAtomically(path, std::string(flash.begin(), flash.end()), error);
}

std::optional<WheelCalibration> storedWheels(const std::vector<uint8_t>& flash) {
  const uint32_t at = WheelRecord::kFlashAddress - kFlashBase;
  if (flash.size() < at + WheelRecord::kWords * 4u) return std::nullopt;
  uint32_t words[WheelRecord::kWords];
  for (int i = 0; i < WheelRecord::kWords; ++i) {
    const uint8_t* b = flash.data() + at + 4 * i;
    words[i] = b[0] | (uint32_t{b[1]} << 8) | (uint32_t{b[2]} << 16) | (uint32_t{b[3]} << 24);
  }
  WheelCalibration w;
  if (!WheelRecord::decode(words, w)) return std::nullopt;
  return w;
}

void storeWheels(std::vector<uint8_t>& flash, const WheelCalibration& w) {
  const uint32_t at = WheelRecord::kFlashAddress - kFlashBase;
  if (flash.size() < at + WheelRecord::kWords * 4u) flash.resize(kFlashSize, 0xFF);
  uint32_t words[WheelRecord::kWords];
  WheelRecord::encode(w, words);
  for (int i = 0; i < WheelRecord::kWords; ++i)
    for (int b = 0; b < 4; ++b) flash[at + 4 * i + b] = static_cast<uint8_t>(words[i] >> (8 * b));
}

ElfImage withStoredWheels(const ElfImage& image, const WheelCalibration& w) {
  std::vector<uint8_t> flash = image.flash();
  storeWheels(flash, w);
  ElfImage stored = image;
  stored.keepPagesFrom(flash);
  return stored;
}

std::string wheelsText(const WheelCalibration& w) {
  char text[64];
  std::snprintf(text, sizeof text, "drift %+.2f deg/m, turns %+.2f %%", w.driftUradPerM * 1e-6 * 57.29577951,
                w.turnPpm * 1e-4);
  return text;
}

}  // namespace nxtmap::emu
