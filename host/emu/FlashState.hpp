// FlashState: the emulated brick's flash kept in a file from one run to the next (`nxtmap emulate
// --flash-keep FILE`), as a brick keeps it while switched off. The file holds the whole 256 KiB flash as the
// last run left it; a new run loads its firmware image as usual and takes the pages above the image from the
// file (ElfImage::keepPagesFrom): what the firmware stored there (the learnt wheels, WheelRecord) survives,
// while a new firmware replaces the old one's code.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/motion/PoseTracker.hpp"
#include "host/emu/ElfImage.hpp"

namespace nxtmap::emu {

// The file's flash: nullopt and no error when it does not exist yet (a brick never switched on); nullopt
// with `error` ("PATH: <reason>") when it is not a regular file of exactly 262,144 bytes.
std::optional<std::vector<uint8_t>> readFlashState(const std::string& path, std::string& error);
// Writes `flash` (262,144 bytes) whole or not at all (fileio::AtomicFile). False with `error`.
bool writeFlashState(const std::string& path, const std::vector<uint8_t>& flash, std::string& error);
// The learnt wheels our firmware keeps in `flash` (the whole 256 KiB), if a whole WheelRecord is there.
std::optional<WheelCalibration> storedWheels(const std::vector<uint8_t>& flash);
// Writes `w` into `flash` (the whole 256 KiB) as our firmware keeps it (WheelRecord in its page).
void storeWheels(std::vector<uint8_t>& flash, const WheelCalibration& w);
// `image` with `w` in the flash page the firmware keeps its wheels in: a brick that was calibrated before.
ElfImage withStoredWheels(const ElfImage& image, const WheelCalibration& w);
// "drift +0.12 deg/m, turns -1.50 %" (one sigma omitted): a wheel calibration as people read it.
std::string wheelsText(const WheelCalibration& w);

}  // namespace nxtmap::emu
