#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/PackedCells.hpp"
#include "common/grid/RoomGrid.hpp"
#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {

// The brick's "nothing lost" bookkeeping for the map. It keeps a shadow of the grid: for every
// cell the state the PC was last sent (2 bits, value 3 = "must be sent again"). A cell whose
// grid state differs from its shadow is pending. buildDelta() packs pending cells into a
// MapDelta (absolute states, so duplicates and late copies are harmless), sets their shadow,
// and remembers the delta's runs under its sequence number. When the PC acknowledges the
// sequence number the record is dropped; when it times out, or the link drops, the shadow of
// its cells becomes 3 so they are sent again with their state at that time. Hence, once the
// grid stops changing and the link carries packets again, the PC's copy equals the grid.
//
// A new epoch (restart(): new room, restructuring, the PC asked for the whole map) sets the
// shadow to "unknown everywhere", the state the PC's copy has after it clears it on seeing
// the epoch; the first delta of an epoch is sent even when it carries no cells.
//
// The size of a delta adapts to the link (as TCP's window does): halved whenever a delta times
// out, grown by kGrowBytes with every acknowledged one, between kMinDeltaPayload and
// kMaxPayload. On a clean link deltas are as large as a frame allows; when bytes are damaged,
// small frames get through where large ones would almost never (5 % bad bytes: a 128-byte frame
// arrives intact 0.1 % of the time, a 32-byte one 19 %).
//
// Cost (the brick runs this inside its 1 ms step): the grid is compared with the shadow 4 bytes
// at a time (PackedDiff) and only differing bytes are decoded, so a scan that finds nothing
// reads the two 1 KiB tori once; a delta decodes only the cells it sends plus the gaps its runs
// bridge. A full delta remembers where it stopped and the next scan resumes there (wrapping
// round), so changes late in the grid are not starved by changes early in it.
//
// Memory: the shadow is caller-owned (packedBytes(w, h, 2), 1 KiB for 64 x 64) plus
// kSlots records of kRunsPerSlot runs (about 0.5 KiB).
class MapSync {
 public:
  // Work done by the scans since construction (for benchmarks): scans (buildDelta and pending
  // calls), bytes compared, cells decoded one by one.
  struct Work {
    uint32_t scans = 0;
    uint32_t bytesCompared = 0;
    uint32_t cellsExamined = 0;
  };

  static constexpr int kSlots = 6;
  static constexpr int kRunsPerSlot = 25;  // a payload holds at most (112 - 12) / 4 = 25 runs
  static constexpr uint8_t kMaxGap = 8;    // unchanged cells a run may bridge (cheaper than a new run)
  static constexpr size_t kGrowBytes = 8;
  static constexpr uint32_t kMinRtoMs = 30;
  static constexpr uint32_t kRtoMarginMs = 20;

  // `shadow`: packedBytes(grid.capacityWidth(), grid.capacityHeight(), 2) bytes, caller-owned.
  MapSync(const RoomGrid& grid, uint8_t* shadow, uint32_t retransmitMs);

  // Starts a new epoch (see above). Records in flight are forgotten.
  void restart();
  // The link dropped: everything in flight must be sent again.
  void linkLost();

  // Builds the next delta into `out` when anything is pending and a record is free, and
  // remembers it under `seq` (sent at `nowMs`). Returns false when there is nothing to send.
  bool buildDelta(uint16_t seq, uint32_t nowMs, Payload& out);
  // The PC's ack/ackMask arrived at `nowMs`: drops the records they cover and updates the
  // round-trip estimate.
  void acknowledge(uint16_t ack, uint16_t ackMask, uint32_t nowMs);
  // Records older than the retransmission timeout are given up: their cells are pending again.
  // The timeout adapts as TCP's does: twice the smoothed round trip plus kRtoMarginMs, between
  // kMinRtoMs and the configured retransmitMs (which is also the start value).
  // Returns how many records timed out.
  int expire(uint32_t nowMs);

  // Whether any cell is pending (compares the grid with the shadow, 4 bytes at a time).
  bool pending() const;
  // The first pending cell (torus index) in [from, end), or `end` when there is none.
  uint32_t nextPending(uint32_t from, uint32_t end) const;
  // Where the next delta's scan starts (torus index, a multiple of 4): after a full delta, the
  // first cell of the byte holding the first pending cell it left out; 0 after restart().
  uint32_t resumeIndex() const { return resume_; }
  const Work& work() const { return work_; }
  int inFlight() const;
  uint16_t epoch() const { return epoch_; }
  uint32_t retransmitMs() const { return retransmitMs_; }
  size_t payloadLimit() const { return payloadLimit_; }
  uint32_t retransmitTimeoutMs() const { return rtoMs_; }
  uint8_t widthLog2() const;
  uint8_t heightLog2() const;

 private:
  struct Slot {
    bool used;
    uint8_t runCount;
    uint16_t seq;
    uint32_t sentMs;
    uint16_t runIndex[kRunsPerSlot];  // first torus index of each run
    uint8_t runCells[kRunsPerSlot];   // cells in each run
  };

  bool cellPending(uint32_t index) const;
  // Adds runs of the pending cells in [i, end) to the delta. Returns false when the delta is
  // full; `i` is then the first pending cell left out.
  bool addRuns(uint32_t& i, uint32_t end, MapDeltaWriter& writer, Slot& slot);
  uint32_t cellsToWindowEdge(uint32_t i) const;
  void forget(Slot& s);  // cells of the record become pending; the record is dropped
  Slot* freeSlot();
  // Detects a grid restructured or cleared behind our back: the window no longer contains the old one.
  void followWindow();

  const RoomGrid& grid_;
  PackedCells<2> shadow_;
  uint32_t retransmitMs_;
  uint32_t srttMs_ = 0;  // smoothed round trip, valid once measured_
  uint32_t rtoMs_;
  Bounds lastWindow_{};
  mutable Work work_;
  uint16_t epoch_ = 0;
  uint16_t payloadLimit_ = kMaxPayload;  // kMinDeltaPayload .. kMaxPayload bytes
  uint16_t resume_ = 0;                  // torus index where the next scan starts
  bool announce_ = true;                 // the epoch's first delta is still to be sent
  bool measured_ = false;
  Slot slots_[kSlots] = {};
};

static_assert(sizeof(MapSync) <= 640, "MapSync bookkeeping on the brick: <= 640 bytes besides the shadow");

}  // namespace nxtmap::protocol
