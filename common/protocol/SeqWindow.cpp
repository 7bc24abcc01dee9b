#include "common/protocol/SeqWindow.hpp"

namespace nxtmap::protocol {
namespace {
// Signed distance from `from` to `to` on the 16-bit circle, skipping nothing (seq 0 is rare).
int distance(uint16_t from, uint16_t to) { return static_cast<int16_t>(static_cast<uint16_t>(to - from)); }
}  // namespace

bool SeqWindow::seen(uint16_t seq) const {
  if (seq == 0 || !any_) return false;
  const int d = distance(newest_, seq);
  if (d > 0) return false;
  if (d == 0) return true;
  if (d < -16) return true;
  return ((mask_ >> (-d - 1)) & 1u) != 0;
}

void SeqWindow::record(uint16_t seq) {
  if (seq == 0) return;
  if (!any_) {
    any_ = true;
    newest_ = seq;
    mask_ = 0;
    return;
  }
  const int d = distance(newest_, seq);
  if (d > 0) {
    // Shift the old newest into the mask: it is now d behind.
    const uint32_t shifted = d >= 17 ? 0u : ((static_cast<uint32_t>(mask_) << d) | (1u << (d - 1)));
    mask_ = static_cast<uint16_t>(shifted);
    newest_ = seq;
  } else if (d < 0 && d >= -16) {
    mask_ = static_cast<uint16_t>(mask_ | (1u << (-d - 1)));
  }
}

}  // namespace nxtmap::protocol
