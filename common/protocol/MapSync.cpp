#include "common/protocol/MapSync.hpp"

#include "common/protocol/Packet.hpp"
#include "common/protocol/PackedDiff.hpp"

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
    : grid_(grid),
      shadow_(shadow, grid.capacityWidth(), grid.capacityHeight()),
      retransmitMs_(retransmitMs),
      rtoMs_(retransmitMs) {
  restart();  // epoch 1
}

void MapSync::restart() {
  shadow_.fill(static_cast<uint8_t>(CellState::Unknown));
  for (Slot& s : slots_) s.used = false;
  epoch_ = static_cast<uint16_t>(epoch_ + 1);
  announce_ = true;
  lastWindow_ = grid_.window();
  resume_ = 0;
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
  ++work_.cellsExamined;
  return shadow_.atIndex(index) != grid_.cells().atIndex(index);
}

bool MapSync::pending() const {
  ++work_.scans;
  const uint32_t total = static_cast<uint32_t>(shadow_.bytes()) * 4u;
  return nextPending(0, total) < total;
}

uint32_t MapSync::nextPending(uint32_t from, uint32_t end) const {
  // Same capacity, same torus indexing: byte k of both holds cells 4k .. 4k+3.
  const uint8_t* shadow = shadow_.data();
  const uint8_t* cells = grid_.cells().data();
  uint32_t i = from;
  while (i < end) {
    if ((i & 3u) == 0) {
      const uint32_t wholeEnd = end >> 2;  // bytes entirely inside [i, end)
      const uint32_t b = static_cast<uint32_t>(firstDifference(shadow, cells, i >> 2, wholeEnd));
      work_.bytesCompared += b - (i >> 2) + (b < wholeEnd ? 1u : 0u);
      i = b << 2;
      if (b < wholeEnd) return i + lowestCell(differingCells(shadow[b], cells[b]));
      if (i >= end) break;
    }
    if (cellPending(i)) return i;  // a partial byte at either end of the range
    ++i;
  }
  return end;
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
  MapDeltaWriter writer(out, header, payloadLimit_);
  slot->runCount = 0;

  // From where the last full delta stopped to the end, then round from 0.
  ++work_.scans;
  const uint32_t total = static_cast<uint32_t>(cells.width()) * static_cast<uint32_t>(cells.height());
  const uint32_t start = resume_ < total ? resume_ : 0;
  uint32_t i = start;
  bool room = addRuns(i, total, writer, *slot);
  if (room && start > 0) {
    i = 0;
    room = addRuns(i, start, writer, *slot);
  }
  resume_ = static_cast<uint16_t>((room ? start : i) & ~3u);  // whole bytes: the scans stay byte-wise
  if (slot->runCount == 0 && !announce_) return false;
  announce_ = false;
  slot->used = true;
  slot->seq = seq;
  slot->sentMs = nowMs;
  return true;
}

bool MapSync::addRuns(uint32_t& i, uint32_t end, MapDeltaWriter& writer, Slot& slot) {
  const uint8_t* cells = grid_.cells().data();
  uint8_t* shadow = shadow_.data();
  const uint32_t w = static_cast<uint32_t>(grid_.cells().width());
  while (true) {
    i = nextPending(i, end);
    if (i >= end) return true;
    if (slot.runCount == kRunsPerSlot) return false;
    // A run from i along the row (and inside [i, end)): up to kMaxRunCells cells, bridging
    // gaps of up to kMaxGap, and no more than the payload can take.
    const uint32_t rowEnd = (i & ~(w - 1u)) + w;  // w is a power of two (no division on the ARM7)
    const uint32_t windowEnd = i + cellsToWindowEdge(i);
    uint32_t limit = rowEnd < end ? rowEnd : end;
    if (windowEnd < limit) limit = windowEnd;  // a gap bridged past the window would name cells outside it
    if (limit - i > kMaxRunCells) limit = i + kMaxRunCells;
    const size_t room = writer.cellsThatFit();
    if (limit - i > room) limit = i + static_cast<uint32_t>(room);
    if (limit == i) return false;  // payload full
    uint32_t last = i;
    uint32_t j = i + 1;
    for (; j < limit && j - last <= kMaxGap; ++j) {
      if (cellDiffers(shadow, cells, j)) last = j;
    }
    work_.cellsExamined += j - i;
    const uint32_t base = i;
    const uint32_t count = last - i + 1;
    uint8_t packed[(kMaxRunCells + 3) / 4];
    extractCells(cells, base, count, packed);
    if (!writer.addPackedRun(static_cast<uint16_t>(base), static_cast<uint8_t>(count), packed)) return false;
    copyCells(cells, shadow, base, count);
    slot.runIndex[slot.runCount] = static_cast<uint16_t>(base);
    slot.runCells[slot.runCount] = static_cast<uint8_t>(count);
    ++slot.runCount;
    i = base + count;
  }
}

// Cells from torus index i (a pending cell, so inside the window) to the window's right edge along
// its row, i's own included (1..width). A window narrower than the capacity leaves torus columns that
// unwrap to no cell of it.
uint32_t MapSync::cellsToWindowEdge(uint32_t i) const {
  const Bounds win = grid_.window();
  const int w = grid_.cells().width();
  const int x = win.minX + ((static_cast<int>(i & static_cast<uint32_t>(w - 1)) - win.minX) & (w - 1));
  return win.maxX >= x ? static_cast<uint32_t>(win.maxX - x + 1) : 1u;
}

void MapSync::acknowledge(uint16_t ack, uint16_t ackMask, uint32_t nowMs) {
  for (Slot& s : slots_) {
    if (s.used && acknowledges(ack, ackMask, s.seq)) {
      s.used = false;
      const uint32_t sample = nowMs - s.sentMs;
      srttMs_ = measured_ ? (7 * srttMs_ + sample) / 8 : sample;
      measured_ = true;
      const uint32_t rto = 2 * srttMs_ + kRtoMarginMs;
      rtoMs_ = rto < kMinRtoMs ? kMinRtoMs : (rto > retransmitMs_ ? retransmitMs_ : rto);
      payloadLimit_ =
          static_cast<uint16_t>(payloadLimit_ + kGrowBytes > kMaxPayload ? kMaxPayload : payloadLimit_ + kGrowBytes);
    }
  }
}

int MapSync::expire(uint32_t nowMs) {
  int n = 0;
  for (Slot& s : slots_) {
    if (s.used && nowMs - s.sentMs >= rtoMs_) {
      forget(s);
      payloadLimit_ =
          static_cast<uint16_t>(payloadLimit_ / 2 < kMinDeltaPayload ? kMinDeltaPayload : payloadLimit_ / 2);
      ++n;
    }
  }
  return n;
}

void MapSync::forget(Slot& s) {
  for (uint8_t r = 0; r < s.runCount; ++r) {
    setCells(shadow_.data(), s.runIndex[r], s.runCells[r], kMustSend);
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
