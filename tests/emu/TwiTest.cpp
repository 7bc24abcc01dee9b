// The TWI master at register level, from the AT91SAM7S datasheet's TWI chapter, with the AVR behind it:
// a write frame (MREAD 0) starts at the first THR byte or at CR.START (START and the address at once),
// each byte moves from THR into the shifter at the end of the one before (TXRDY), and the STOP follows by
// itself when THR and the shifter are empty; TXCOMP is clear from the frame's start to its STOP. STOP
// asked in a write (defined by later TWI datasheets: after the data byte on the wire) ends the frame
// there, and a byte still in THR goes out in a frame of its own. Reads: START, STOP while the last byte
// arrives.
#include "host/emu/Twi.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCr = 0x00, kMmr = 0x04, kCwgr = 0x10, kSr = 0x20, kRhr = 0x30, kThr = 0x34;
constexpr uint32_t kStart = 1, kStop = 2, kMsen = 4;
constexpr uint32_t kTxcomp = 1, kRxrdy = 2, kTxrdy = 4, kNack = 1u << 8;
constexpr uint32_t kAvr = 1u << 16, kMread = 1u << 12;
constexpr uint32_t kCldiv = 57;                   // 400 kHz at 48 MHz, as LEGO's d_ioctrl.r and our AvrLink set it
constexpr uint64_t kByte = 9 * 2 * (kCldiv + 3);  // MCK cycles per byte on the wire (9 SCL periods)

struct Rig {
  Clock clock;
  AvrModel avr;
  Twi twi{clock, avr};
  Rig() {
    set(kCwgr, kCldiv | (kCldiv << 8));
    set(kCr, kMsen);
  }
  void set(uint32_t off, uint32_t v) { EXPECT_TRUE(twi.write(off, v)) << off; }
  uint32_t sr() {
    uint32_t v = 0;
    EXPECT_TRUE(twi.read(kSr, v));
    return v;
  }
  // Runs the bus for `cycles` MCK cycles, event by event.
  void run(uint64_t cycles) {
    const uint64_t end = clock.now + cycles;
    while (twi.nextEventAt() <= end) {
      clock.now = twi.nextEventAt();
      twi.advanceTo(clock.now);
    }
    clock.now = end;
  }
};

// A 9-byte command frame the AVR obeys: motor A at `power`, checksum last.
std::vector<uint8_t> command(int8_t power) {
  std::vector<uint8_t> f = {0, 8, static_cast<uint8_t>(power), 0, 0, 0, 0, 0, 0};
  unsigned sum = 0;
  for (size_t i = 0; i < 8; ++i) sum += f[i];
  f[8] = static_cast<uint8_t>(~sum);
  return f;
}

// How a firmware writes a frame: the first byte to THR at once, each next one when TXRDY is set (as an
// interrupt handler would, a few cycles after it rises).
struct WriteRow {
  const char* what;
  bool startFirst;       // CR.START before anything is in THR
  uint64_t firstByteAt;  // cycles after the START (or at once) the first byte is written to THR
  bool stopBeforeLast;   // CR.STOP written just before the last byte, while the one before is on the wire
  size_t bytes;          // of the command frame, 0 = none written at all
  uint64_t frames;       // frames the TWI ended with a STOP
  uint64_t good, bad;    // as the AVR judged them
  int power;             // motor A afterwards
};

TEST(TwiModel, WriteFramesStartEndAndSplitAsTheDatasheetSays) {
  const WriteRow rows[] = {
      {"THR starts the frame, the STOP comes by itself", false, 0, false, 9, 1, 1, 0, 40},
      {"START then THR within the address byte: one frame", true, kByte / 3, false, 9, 1, 1, 0, 40},
      {"START alone: the address, then the automatic STOP", true, 0, false, 0, 1, 0, 0, 0},
      {"START, THR only after the address went: an empty frame, then the data in a frame of its own", true, kByte + 10,
       false, 9, 2, 1, 0, 40},
      {"STOP asked before the last byte: the frame ends after the byte on the wire, the last byte alone", false, 0,
       true, 9, 2, 0, 2, 0},
      {"START and STOP before the last byte (our firmware until now)", true, 5, true, 9, 2, 0, 2, 0},
  };
  for (const WriteRow& r : rows) {
    Rig g;
    g.set(kMmr, kAvr);
    const std::vector<uint8_t> f = command(40);
    if (r.startFirst) {
      g.set(kCr, kStart);
      EXPECT_EQ(g.sr() & kTxcomp, 0u) << r.what << ": TXCOMP clear once the frame started";
    }
    g.run(r.firstByteAt);
    for (size_t i = 0; i < r.bytes; ++i) {
      if (i > 0) {
        for (int guard = 0; !(g.sr() & kTxrdy) && guard < 100; ++guard) g.run(20);
        ASSERT_TRUE(g.sr() & kTxrdy) << r.what;
      }
      if (r.stopBeforeLast && i + 1 == r.bytes) g.set(kCr, kStop);
      g.set(kThr, f[i]);
      EXPECT_EQ(g.sr() & kTxcomp, 0u) << r.what << ": TXCOMP clear while byte " << i << " waits";
    }
    g.run(20 * kByte);
    EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), kTxcomp | kTxrdy) << r.what << ": the STOP went out";
    EXPECT_EQ(g.twi.frames(), r.frames) << r.what;
    EXPECT_EQ(g.avr.goodFrames(), r.good) << r.what;
    EXPECT_EQ(g.avr.badFrames(), r.bad) << r.what;
    EXPECT_EQ(g.avr.motorPower(0), r.power) << r.what;
  }
}

TEST(TwiModel, TxcompFollowsTheFrameByteByByte) {
  // Status after each event of a 2-byte write started by THR: the address, byte 0, byte 1, STOP.
  Rig g;
  g.set(kMmr, kAvr);
  EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), kTxcomp | kTxrdy) << "idle, master enabled";
  g.set(kThr, 0x11);
  EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), 0u) << "byte 0 waits in THR behind the address";
  g.run(kByte);
  EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), kTxrdy) << "byte 0 in the shifter";
  g.set(kThr, 0x22);
  g.run(kByte);
  EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), kTxrdy) << "byte 1 in the shifter";
  g.run(kByte - 1);
  EXPECT_EQ(g.sr() & kTxcomp, 0u) << "byte 1 still on the wire";
  g.run(1);
  EXPECT_EQ(g.sr() & (kTxcomp | kTxrdy), kTxcomp | kTxrdy) << "THR and shifter empty: STOP, TXCOMP";
  EXPECT_EQ(g.twi.frames(), 1u);
}

TEST(TwiModel, ReadsStartWithStartAndEndAfterTheByteDuringWhichStopWasAsked) {
  Rig g;
  g.set(kMmr, kAvr | kMread);
  g.set(kCr, kStart);
  EXPECT_EQ(g.sr() & kTxcomp, 0u);
  uint8_t bytes[13] = {};
  for (int i = 0; i < 13; ++i) {
    for (int guard = 0; !(g.sr() & kRxrdy) && guard < 1000; ++guard) g.run(20);
    uint32_t v = 0;
    ASSERT_TRUE(g.twi.read(kRhr, v));
    bytes[i] = static_cast<uint8_t>(v);
    if (i == 11) g.set(kCr, kStop);
  }
  g.run(2 * kByte);
  EXPECT_EQ(g.sr() & (kTxcomp | kRxrdy | kNack), kTxcomp);  // no 14th byte
  unsigned sum = 0;
  for (uint8_t b : bytes) sum += b;
  EXPECT_EQ(sum & 0xFF, 0xFFu);  // the AVR's 13-byte status, checksum included
  EXPECT_EQ(g.twi.frames(), 1u);
}

TEST(TwiModel, AFrameToAnotherAddressIsNacked) {
  Rig g;
  g.set(kMmr, 5u << 16);
  g.set(kThr, 0x11);
  g.run(2 * kByte);
  const uint32_t sr = g.sr();
  EXPECT_EQ(sr & (kNack | kTxcomp), kNack | kTxcomp);
  EXPECT_EQ(g.sr() & kNack, 0u);  // cleared by the read
  EXPECT_EQ(g.avr.goodFrames() + g.avr.badFrames(), 0u);
}

}  // namespace
}  // namespace nxtmap::emu::test
