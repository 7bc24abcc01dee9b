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
// Memory: the shadow is caller-owned (packedBytes(w, h, 2), 1 KiB for 64 x 64) plus
// kSlots records of kRunsPerSlot runs (about 0.4 KiB).
class MapSync {
 public:
  static constexpr int kSlots = 4;
  static constexpr int kRunsPerSlot = 25;  // a payload holds at most (112 - 12) / 4 = 25 runs
  static constexpr uint8_t kMaxGap = 8;    // unchanged cells a run may bridge (cheaper than a new run)

  // `shadow`: packedBytes(grid.capacityWidth(), grid.capacityHeight(), 2) bytes, caller-owned.
  MapSync(const RoomGrid& grid, uint8_t* shadow, uint32_t retransmitMs);

  // Starts a new epoch (see above). Records in flight are forgotten.
  void restart();
  // The link dropped: everything in flight must be sent again.
  void linkLost();

  // Builds the next delta into `out` when anything is pending and a record is free, and
  // remembers it under `seq` (sent at `nowMs`). Returns false when there is nothing to send.
  bool buildDelta(uint16_t seq, uint32_t nowMs, Payload& out);
  // The PC's ack/ackMask arrived: drops the records they cover.
  void acknowledge(uint16_t ack, uint16_t ackMask);
  // Records older than the retransmission time are given up: their cells are pending again.
  // Returns how many records timed out.
  int expire(uint32_t nowMs);

  // Whether any cell is pending (scans the grid: about 1 KiB of byte compares).
  bool pending() const;
  int inFlight() const;
  uint16_t epoch() const { return epoch_; }
  uint32_t retransmitMs() const { return retransmitMs_; }
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
  void forget(Slot& s);  // cells of the record become pending; the record is dropped
  Slot* freeSlot();
  // Detects a grid restructured or cleared behind our back: the window no longer contains the old one.
  void followWindow();

  const RoomGrid& grid_;
  PackedCells<2> shadow_;
  uint32_t retransmitMs_;
  uint16_t epoch_ = 0;
  bool announce_ = true;  // the epoch's first delta is still to be sent
  Bounds lastWindow_{};
  Slot slots_[kSlots] = {};
};

static_assert(sizeof(MapSync) <= 512, "MapSync bookkeeping on the brick: <= 512 bytes besides the shadow");

}  // namespace nxtmap::protocol
