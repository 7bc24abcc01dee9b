#include "host/cli/LcdSeries.hpp"

#include <cstdio>
#include <filesystem>

namespace nxtmap::cli {

std::string LcdSeries::numbered(const std::string& base, int n) {
  const std::filesystem::path p(base);
  const std::string ext = p.has_extension() ? p.extension().string() : ".png";
  char digits[8];
  std::snprintf(digits, sizeof digits, "%04d", n);
  std::filesystem::path out = p;
  out.replace_filename(p.stem().string() + "-" + digits + ext);
  return out.string();
}

bool LcdSeries::poll(uint64_t now, const emu::Lcd& lcd, std::string& error) {
  while (now >= static_cast<uint64_t>(written_ + 1) * period_) {
    if (written_ >= kMaxPictures) {
      error = "--lcd-every: more than " + std::to_string(kMaxPictures) + " pictures; choose a longer period";
      return false;
    }
    if (!lcd.savePng(numbered(base_, written_ + 1), 4, error)) return false;
    ++written_;
  }
  return true;
}

}  // namespace nxtmap::cli
