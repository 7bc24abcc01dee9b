#pragma once
#include <cstdint>

// Command-mode framing of the BlueCore (BC4) module running LEGO's Bluetooth firmware:
// [len][code][payload...][sum_hi][sum_lo], len = bytes after it. The two directions use different
// checksum rules: ARM -> BC4 sums code + payload only; BC4 -> ARM also sums the length byte. Both are
// the 16-bit two's complement of the sum, big-endian.
namespace nxtmap::fw {

namespace bc {
// ARM -> BC4
constexpr uint8_t kOpenPort = 0x03, kAcceptConnection = 0x09, kPinCode = 0x0A, kOpenStream = 0x0B,
                  kSetDiscoverable = 0x1C;
// BC4 -> ARM
constexpr uint8_t kConnectResult = 0x13, kResetIndication = 0x14, kRequestPinCode = 0x15, kRequestConnection = 0x16,
                  kPortOpenResult = 0x1B;
}  // namespace bc

constexpr uint8_t kBcMaxPayload = 32;

inline uint16_t bcChecksum(const uint8_t* bytes, uint8_t n) {
  uint16_t sum = 0;
  for (uint8_t i = 0; i < n; ++i) sum = static_cast<uint16_t>(sum + bytes[i]);
  return static_cast<uint16_t>(0u - sum);
}

// Encodes one ARM -> BC4 command into out (payloadLen + 4 bytes); returns the byte count, 0 if too long.
inline uint8_t encodeBcCommand(uint8_t code, const uint8_t* payload, uint8_t payloadLen, uint8_t* out) {
  if (payloadLen > kBcMaxPayload) return 0;
  out[0] = static_cast<uint8_t>(payloadLen + 3);
  out[1] = code;
  for (uint8_t i = 0; i < payloadLen; ++i) out[2 + i] = payload[i];
  const uint16_t sum = bcChecksum(out + 1, static_cast<uint8_t>(payloadLen + 1));  // length excluded
  out[2 + payloadLen] = static_cast<uint8_t>(sum >> 8);
  out[3 + payloadLen] = static_cast<uint8_t>(sum & 0xFF);
  return static_cast<uint8_t>(payloadLen + 4);
}

// Byte-at-a-time decoder of BC4 -> ARM messages (checksum includes the length byte).
class BcParser {
 public:
  // Feeds one byte; true when it completed a message with a good checksum (see code()/payload()).
  bool push(uint8_t b) {
    if (pos_ == 0) {
      if (b < 3 || b > kBcMaxPayload + 3) {  // not a plausible length: resynchronise on the next byte
        ++bad_;
        return false;
      }
      need_ = static_cast<uint8_t>(b + 1);
    }
    buf_[pos_++] = b;
    if (pos_ < need_) return false;
    pos_ = 0;
    const uint8_t n = static_cast<uint8_t>(need_ - 2);  // len + code + payload
    const uint16_t got = static_cast<uint16_t>((buf_[n] << 8) | buf_[n + 1]);
    if (got != bcChecksum(buf_, n)) {
      ++bad_;
      return false;
    }
    return true;
  }
  void reset() { pos_ = 0; }
  uint8_t code() const { return buf_[1]; }
  const uint8_t* payload() const { return buf_ + 2; }
  uint8_t payloadLength() const { return static_cast<uint8_t>(buf_[0] - 3); }
  uint32_t badMessages() const { return bad_; }

 private:
  uint8_t buf_[kBcMaxPayload + 4] = {};
  uint8_t pos_ = 0, need_ = 0;
  uint32_t bad_ = 0;
};

}  // namespace nxtmap::fw
