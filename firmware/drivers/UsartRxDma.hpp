#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/board/Mmio.hpp"

namespace nxtmap::fw {

// USART1 reception through its PDC, two buffers of kBufferBytes chained as current (RPR/RCR) and
// next (RNPR/RNCR), read by polling the counters (no interrupt), as LEGO's d_bt.r does (2 x 128 there).
// Why the PDC: with US_MR USMODE = hardware handshaking the USART drives RTS high (the BlueCore must
// not send) whenever the PDC's RXBUFF is set, i.e. RCR = RNCR = 0; receiving byte by byte with the
// PDC idle would hold RTS high for ever. Here RTS is high only while both buffers hold unread bytes.
// Ownership: buffer `cur_` is the one read from; the PDC fills it (RNCR != 0, next = the other one)
// or has filled it and moved on to the other (RNCR = 0). Single consumer (main loop). Bus: read, write, address (PDC bus address).
template <class Bus>
class UsartRxDma {
 public:
  static constexpr uint16_t kBufferBytes = 64;  // 1.4 ms of bytes at 460800 baud; RTS holds the rest back

  explicit UsartRxDma(Bus& bus) : bus_(bus) {}

  // Arms both buffers and starts the receive PDC (PDC off and receiver enabled by the caller).
  void start() {
    using namespace reg;
    cur_ = 0;
    out_ = 0;
    bus_.write(kUs1Rpr, bus_.address(&buf_[0][0]));
    bus_.write(kUs1Rcr, kBufferBytes);
    bus_.write(kUs1Rnpr, bus_.address(&buf_[1][0]));
    bus_.write(kUs1Rncr, kBufferBytes);
    bus_.write(kUs1Ptcr, 1u << 0);  // RXTEN
  }

  // Bytes received and not read yet in the current buffer (0..kBufferBytes).
  uint16_t pending() const { return static_cast<uint16_t>(filled() - out_); }

  // The next received byte. A buffer read to its end is handed back to the PDC as the next one (at
  // the call after its last byte, once the PDC has moved on: RNCR = 0).
  bool pop(uint8_t& b) {
    using namespace reg;
    if (out_ == kBufferBytes) {
      if (bus_.read(kUs1Rncr) != 0) return false;
      compilerBarrier();  // every byte of the buffer loaded before the PDC may fill it again
      bus_.write(kUs1Rnpr, bus_.address(&buf_[cur_][0]));
      bus_.write(kUs1Rncr, kBufferBytes);
      cur_ ^= 1u;
      out_ = 0;
    }
    if (out_ >= filled()) return false;
    compilerBarrier();  // the byte loaded after the counters that say it is there
    b = buf_[cur_][out_++];
    return true;
  }

  // Forgets every byte received so far (bytes keep arriving 20 us apart at most: the loop ends).
  void clear() {
    uint8_t b;
    while (pop(b)) {}
  }

 private:
  // Bytes the PDC has written into buffer cur_ (>= out_). RCR is read before RNCR: if the PDC moves
  // on between the two reads, RNCR = 0 then says the whole buffer is full, which it is.
  uint16_t filled() const {
    const uint32_t rcr = bus_.read(reg::kUs1Rcr);
    if (bus_.read(reg::kUs1Rncr) == 0) return kBufferBytes;
    return static_cast<uint16_t>(kBufferBytes - rcr);
  }

  Bus& bus_;
  uint8_t buf_[2][kBufferBytes] = {};
  uint8_t cur_ = 0;
  uint16_t out_ = 0;  // bytes of buffer cur_ already read, 0..kBufferBytes
};

}  // namespace nxtmap::fw
