#include "host/emu/AvrModel.hpp"

#include <cstring>

namespace nxtmap::emu {

namespace {
constexpr char kCopyright[] = "Let's samba nxt arm in arm, (c)LEGO System A/S";  // 46 bytes, no space in "(c)LEGO"
}

void AvrModel::receive(const std::vector<uint8_t>& f) {
  if (f.empty()) return;  // an address alone: nothing for the AVR to do
  if (f[0] == 0xCC) {     // the copyright string follows; bytes after it are not looked at
    const size_t n = sizeof kCopyright - 1;
    if (f.size() >= n + 1 && std::memcmp(f.data() + 1, kCopyright, n) == 0) {
      handshake_ = true;
      ++good_;
    } else {
      ++bad_;
    }
    return;
  }
  if (f.size() < kCommandBytes) {  // too short: nothing is taken
    ++bad_;
    return;
  }
  unsigned sum = 0;  // the first kCommandBytes bytes sum to 0xFF; any bytes after them are not looked at
  for (size_t i = 0; i < kCommandBytes; ++i) sum += f[i];
  if ((sum & 0xFF) != 0xFF) {
    ++bad_;
    return;
  }
  ++good_;
  apply(f);
}

void AvrModel::apply(const std::vector<uint8_t>& f) {
  if (f[0] == 0x5A || (f[0] == 0xA5 && f[1] == 0x5A)) powerDown_ = true;
  for (size_t m = 0; m < 4; ++m) {
    int p = static_cast<int8_t>(f[2 + m]);
    power_[m] = static_cast<int8_t>(p < -100 ? -100 : p > 100 ? 100 : p);
  }
  mode_ = f[6];
  inputPower_ = f[7];
}

std::array<uint8_t, 13> AvrModel::reply() const {
  std::array<uint8_t, 13> r{};
  auto put16 = [&](size_t at, unsigned v) {
    r[at] = static_cast<uint8_t>(v & 0xFF);
    r[at + 1] = static_cast<uint8_t>(v >> 8);
  };
  for (size_t p = 0; p < 4; ++p) put16(2 * p, 1023);  // digital sensors leave pin 1 pulled up
  put16(8, buttons_);
  put16(10, static_cast<unsigned>(batteryMv_ * 1000 / 13848) & 0x3FF);
  unsigned sum = 0;
  for (size_t i = 0; i < 12; ++i) sum += r[i];
  r[12] = static_cast<uint8_t>(0xFF - (sum & 0xFF));
  return r;
}

}  // namespace nxtmap::emu
