// LcdSeries: `nxtmap emulate --lcd FILE --lcd-every SECONDS`: the LCD's picture saved every SECONDS of emulated
// time as numbered files beside FILE (dir/lcd.png -> dir/lcd-0001.png at SECONDS, dir/lcd-0002.png at 2 x
// SECONDS, ...), so a run's screens can be followed over time. FILE itself is still the last screen.
#pragma once

#include <cstdint>
#include <string>

#include "host/emu/Lcd.hpp"

namespace nxtmap::cli {

class LcdSeries {
 public:
  static constexpr int kMaxPictures = 9999;
  // base: the --lcd path; period: emulated cycles between pictures (> 0).
  LcdSeries(std::string base, uint64_t periodCycles) : base_(std::move(base)), period_(periodCycles) {}
  // The n-th picture's path (n 1..9999): the base's stem, "-" and n in four digits, the base's extension
  // (".png" when it has none).
  static std::string numbered(const std::string& base, int n);
  // Saves every picture due by emulated cycle `now` (each shows the screen as it is now). False with the
  // reason in error when a file cannot be written or the count would pass kMaxPictures.
  bool poll(uint64_t now, const emu::Lcd& lcd, std::string& error);
  int written() const { return written_; }

 private:
  std::string base_;
  uint64_t period_;
  int written_ = 0;
};

}  // namespace nxtmap::cli
