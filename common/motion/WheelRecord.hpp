#pragma once
#include <cstdint>

#include "common/motion/PoseTracker.hpp"

namespace nxtmap {

// WheelRecord: what a robot learnt of its wheels (WheelCalibration) as the eight 32-bit words the brick keeps
// in a page of its flash, so that it survives switching the brick off. Layout (words, little-endian as the
// ARM stores them):
//   0 kMagic ("NXWh")             4 drift variance, low word    (urad/m)^2
//   1 drift, urad/m (signed)      5 drift variance, high word
//   2 turn error, ppm (signed)    6 turn variance, low word     ppm^2
//   3 kVersion                    7 turn variance, high word  ... and a check word after them (kWords = 9):
//   8 check: kMagic rotated through words 0-7 (checkOf)
// A page that is erased (all ones), written by another firmware, torn by a power cut while programming, or
// holds values outside what wheels do (WheelCalibration's ranges) decodes to nothing: the robot starts as
// an uncalibrated one would.
struct WheelRecord {
  static constexpr uint32_t kMagic = 0x6857584Eu;  // "NXWh"
  static constexpr uint32_t kVersion = 1;
  static constexpr int kWords = 9;
  // The brick keeps the record at the start of the last page of its 256 KiB flash (page 1023 of 256 bytes,
  // 0x13FF00), far above the firmware image (at most 64 KiB). fwflash writes every page, so flashing a
  // firmware forgets the record.
  static constexpr uint32_t kFlashPage = 1023;
  static constexpr uint32_t kFlashAddress = 0x100000u + kFlashPage * 256u;

  static void encode(const WheelCalibration& w, uint32_t (&words)[kWords]);
  // True, and `w` set, when `words` hold a whole record of plausible wheels; else `w` is left as it was.
  static bool decode(const uint32_t (&words)[kWords], WheelCalibration& w);
  // The check word of words 0..kWords-2.
  static uint32_t checkOf(const uint32_t (&words)[kWords]);
  // Whether two calibrations would be stored alike (every field equal).
  static bool same(const WheelCalibration& a, const WheelCalibration& b);
};

}  // namespace nxtmap
