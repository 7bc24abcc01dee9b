#include "common/protocol/MapSync.hpp"

#include "common/protocol/Packet.hpp"

namespace nxtmap::protocol {
namespace {
constexpr uint8_t kMustSend = 3;

uint8_t log2Of(int16_t v) {
  uint8_t k = 0;
  while ((1 << k) < v) ++k;
  return k;
}

bool containsBox(const Bounds& outer, const Bounds& inner) {
  if (inner.empty()) return true;
  if (outer.empty()) return false;
  return inner.minX >= outer.minX && inner.maxX <= outer.maxX && inner.minY >= outer.minY && inner.maxY <= outer.maxY;
}
}  // namespace

MapSync::MapSync(const RoomGrid& grid, uint8_t* shadow, uint32_t retransmitMs)
    : grid_(grid), shadow_(shadow, grid.capacityWidth(), grid.capacityHeight()), retransmitMs_(retransmitMs) {
  restart();  // epoch 1
}

void MapSync::restart() {
  shadow_.fill(static_cast<uint8_t>(CellState::Unknown));
  for (Slot& s : slots_) s.used = false;
  epoch_ = static_cast<uint16_t>(epoch_ + 1);
  announce_ = true;
  lastWindow_ = grid_.window();
}

void MapSync::linkLost() {
  for (Slot& s : slots_) {
    if (s.used) forget(s);
  }
}

void MapSync::followWindow() {
  const Bounds now = grid_.window();
  if (!containsBox(now, lastWindow_)) restart();
  lastWindow_ = grid_.window();
}

bool MapSync::cellPending(uint32_t index) const {
  return shadow_.atIndex(index) != grid_.cells().atIndex(index);
}

bool MapSync::pending() const {
  const size_t bytes = shadow_.bytes();
  // Byte compare first; the packed layouts are identical (same capacity, same torus indexing).
  const PackedCells<2>& cells = grid_.cells();
  const uint32_t total = static_cast<uint32_t>(cells.width()) * static_cast<uint32_t>(cells.height());
  for (uint32_t i = 0; i < total; i += 4) {
    if (i / 4 < bytes && (shadow_.atIndex(i) != cells.atIndex(i) || shadow_.atIndex(i + 1) != cells.atIndex(i + 1) ||
                          shadow_.atIndex(i + 2) != cells.atIndex(i + 2) || shadow_.atIndex(i + 3) != cells.atIndex(i + 3))) {
      return true;
    }
  }
  return false;
}

MapSync::Slot* MapSync::freeSlot() {
  for (Slot& s : slots_) {
    if (!s.used) return &s;
  }
  return nullptr;
}

bool MapSync::buildDelta(uint16_t seq, uint32_t nowMs, Payload& out) {
  followWindow();
  Slot* slot = freeSlot();
  if (slot == nullptr) return false;
  const PackedCells<2>& cells = grid_.cells();
  MapDeltaHeader header;
  header.epoch = epoch_;
  header.widthLog2 = log2Of(cells.width());
  header.heightLog2 = log2Of(cells.height());
  header.window = grid_.window();
  if (header.window.empty()) header.window = Bounds{};
  MapDeltaWriter writer(out, header);
  slot->runCount = 0;

  const uint32_t w = static_cast<uint32_t>(cells.width());
  const uint32_t total = w * static_cast<uint32_t>(cells.height());
  uint32_t i = 0;
  while (i < total && slot->runCount < kRunsPerSlot) {
    if (!cellPending(i)) {
      ++i;
      continue;
    }
    // A run from i along the row: up to kMaxRunCells cells, bridging gaps of up to kMaxGap.
    const uint32_t rowEnd = (i / w + 1) * w;
    uint32_t last = i;
    for (uint32_t j = i + 1; j < rowEnd && j - i < kMaxRunCells && j - last <= kMaxGap; ++j) {
      if (cellPending(j)) last = j;
    }
    uint32_t count = last - i + 1;
    while (count > 0 && !writer.fits(count)) {
      // Shrink to the last pending cell that fits.
      --count;
      while (count > 0 && !cellPending(i + count - 1)) --count;
    }
    if (count == 0) break;  // payload full
    const uint32_t base = i;
    const bool added = writer.addRun(static_cast<uint16_t>(base), static_cast<uint8_t>(count),
                                     [&](uint8_t k) { return cells.atIndex(base + k); });
    if (!added) break;
    for (uint32_t k = 0; k < count; ++k) shadow_.setIndex(base + k, cells.atIndex(base + k));
    slot->runIndex[slot->runCount] = static_cast<uint16_t>(base);
    slot->runCells[slot->runCount] = static_cast<uint8_t>(count);
    ++slot->runCount;
    i = base + count;
  }
  if (slot->runCount == 0 && !announce_) return false;
  announce_ = false;
  slot->used = true;
  slot->seq = seq;
  slot->sentMs = nowMs;
  return true;
}

void MapSync::acknowledge(uint16_t ack, uint16_t ackMask) {
  for (Slot& s : slots_) {
    if (s.used && acknowledges(ack, ackMask, s.seq)) s.used = false;
  }
}

int MapSync::expire(uint32_t nowMs) {
  int n = 0;
  for (Slot& s : slots_) {
    if (s.used && nowMs - s.sentMs >= retransmitMs_) {
      forget(s);
      ++n;
    }
  }
  return n;
}

void MapSync::forget(Slot& s) {
  for (uint8_t r = 0; r < s.runCount; ++r) {
    for (uint8_t k = 0; k < s.runCells[r]; ++k) shadow_.setIndex(static_cast<uint32_t>(s.runIndex[r]) + k, kMustSend);
  }
  if (s.runCount == 0) announce_ = true;  // an epoch announcement was lost: send it again
  s.used = false;
}

uint8_t MapSync::widthLog2() const { return log2Of(grid_.capacityWidth()); }
uint8_t MapSync::heightLog2() const { return log2Of(grid_.capacityHeight()); }

int MapSync::inFlight() const {
  int n = 0;
  for (const Slot& s : slots_) n += s.used ? 1 : 0;
  return n;
}

}  // namespace nxtmap::protocol
