// The PDC channel pair at register level, from the AT91SAM7S datasheet's PDC chapter: 16-bit counters;
// the next pointer/counter pair becomes the current one when the current counter reaches 0, or at once
// when the next counter is written non-zero while the current counter is 0 (the next counter then reads
// 0); PTCR enables and disables (disable wins), PTSR reads them back; ENDRX/ENDTX when the current
// counter is 0, RXBUFF/TXBUFE when both are.
#include "host/emu/Pdc.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kRpr = 0x00, kRcr = 0x04, kTpr = 0x08, kTcr = 0x0C, kRnpr = 0x10, kRncr = 0x14, kTnpr = 0x18,
                   kTncr = 0x1C, kPtcr = 0x20, kPtsr = 0x24;
constexpr uint32_t kRam = 0x200000;

struct Ram : GuestMemory {
  std::array<uint8_t, 256> bytes{};
  bool readByte(uint32_t a, uint8_t& v) const override {
    if (a < kRam || a >= kRam + bytes.size()) return false;
    v = bytes[a - kRam];
    return true;
  }
  bool writeByte(uint32_t a, uint8_t v) override {
    if (a < kRam || a >= kRam + bytes.size()) return false;
    bytes[a - kRam] = v;
    return true;
  }
};

uint32_t reg(const Pdc& p, uint32_t off) {
  uint32_t v = 0xDEADBEEF;
  EXPECT_TRUE(p.read(off, v)) << off;
  return v;
}

struct Write {
  uint32_t off, value;
};
struct Expect {
  uint32_t off, value;
};
struct Row {
  const char* what;
  std::vector<Write> writes;
  std::vector<Expect> reads;
};

TEST(Pdc, RegisterWritesGiveTheDatasheetsReads) {
  const Row rows[] = {
      {"reset: all zero", {}, {{kRpr, 0}, {kRcr, 0}, {kTpr, 0}, {kTcr, 0}, {kRncr, 0}, {kTncr, 0}, {kPtsr, 0}}},
      {"counters are 16 bits", {{kTcr, 0x12345}, {kRcr, 0x1FFFF}}, {{kTcr, 0x2345}, {kRcr, 0xFFFF}}},
      {"TNCR while TCR = 0: the next buffer is current at once",
       {{kTnpr, kRam + 0x40}, {kTncr, 4}},
       {{kTpr, kRam + 0x40}, {kTcr, 4}, {kTncr, 0}, {kTnpr, kRam + 0x40}}},
      {"RNCR while RCR = 0: likewise",
       {{kRnpr, kRam + 0x80}, {kRncr, 7}},
       {{kRpr, kRam + 0x80}, {kRcr, 7}, {kRncr, 0}}},
      {"TNCR while TCR > 0: waits as the next buffer",
       {{kTpr, kRam}, {kTcr, 2}, {kTnpr, kRam + 0x40}, {kTncr, 3}},
       {{kTpr, kRam}, {kTcr, 2}, {kTnpr, kRam + 0x40}, {kTncr, 3}}},
      {"RNCR while RCR > 0: waits", {{kRpr, kRam}, {kRcr, 1}, {kRnpr, kRam + 8}, {kRncr, 5}}, {{kRcr, 1}, {kRncr, 5}}},
      {"TNCR = 0 while TCR = 0 starts nothing", {{kTnpr, kRam + 0x40}, {kTncr, 0}}, {{kTpr, 0}, {kTcr, 0}}},
      {"TNPR alone starts nothing", {{kTnpr, kRam + 0x40}}, {{kTpr, 0}, {kTcr, 0}, {kTnpr, kRam + 0x40}}},
      {"PTCR RXTEN, TXTEN", {{kPtcr, 0x101}}, {{kPtsr, 0x101}}},
      {"PTCR RXTDIS", {{kPtcr, 0x101}, {kPtcr, 0x2}}, {{kPtsr, 0x100}}},
      {"PTCR TXTDIS", {{kPtcr, 0x101}, {kPtcr, 0x200}}, {{kPtsr, 0x1}}},
      {"PTCR enable and disable together: disabled", {{kPtcr, 0x303}}, {{kPtsr, 0}}},
  };
  for (const Row& r : rows) {
    Ram ram;
    Pdc p(ram);
    for (const Write& w : r.writes) EXPECT_TRUE(p.write(w.off, w.value)) << r.what;
    for (const Expect& e : r.reads) EXPECT_EQ(reg(p, e.off), e.value) << r.what << ", register 0x" << std::hex << e.off;
  }
}

// ENDTX/ENDRX are set whenever the current counter is 0 and TXBUFE/RXBUFF whenever both counters are: levels
// of the counters (cleared only by a counter written non-zero, or chained in), never events a read clears.
// Each row: register writes, transfers taken, then the four flags read twice.
TEST(Pdc, EndAndBufferFlagsAreLevelsOfTheCounters) {
  struct FlagRow {
    const char* what;
    std::vector<Write> writes;
    int txTaken, rxPut;
    bool endTx, txBufe, endRx, rxBuff;
  };
  const FlagRow rows[] = {
      {"reset: both counters 0", {}, 0, 0, true, true, true, true},
      {"TCR written non-zero clears ENDTX and TXBUFE", {{kTpr, kRam}, {kTcr, 2}}, 0, 0, false, false, true, true},
      {"RCR written non-zero clears ENDRX and RXBUFF", {{kRpr, kRam}, {kRcr, 2}}, 0, 0, true, true, false, false},
      {"the last transfer sets ENDTX and TXBUFE again",
       {{kTpr, kRam}, {kTcr, 2}, {kPtcr, 0x100}},
       2,
       0,
       true,
       true,
       true,
       true},
      {"a next buffer waiting: ENDTX, not TXBUFE",
       {{kTpr, kRam}, {kTcr, 1}, {kTnpr, kRam + 8}, {kTncr, 1}, {kPtcr, 0x100}},
       1,
       0,
       false,
       false,
       true,
       true},
      {"both buffers sent",
       {{kTpr, kRam}, {kTcr, 1}, {kTnpr, kRam + 8}, {kTncr, 1}, {kPtcr, 0x100}},
       2,
       0,
       true,
       true,
       true,
       true},
      {"TNCR while TCR = 0 chains at once: ENDTX cleared", {{kTnpr, kRam}, {kTncr, 3}}, 0, 0, false, false, true, true},
      {"TCR written 0 sets ENDTX", {{kTpr, kRam}, {kTcr, 5}, {kTcr, 0}}, 0, 0, true, true, true, true},
      {"receive filled: ENDRX and RXBUFF", {{kRpr, kRam}, {kRcr, 1}, {kPtcr, 1}}, 0, 1, true, true, true, true},
      {"disabled with data left: no ENDTX", {{kTpr, kRam}, {kTcr, 4}, {kPtcr, 0x200}}, 0, 0, false, false, true, true},
  };
  for (const FlagRow& r : rows) {
    Ram ram;
    Pdc p(ram);
    for (const Write& w : r.writes) EXPECT_TRUE(p.write(w.off, w.value)) << r.what;
    for (int i = 0; i < r.txTaken; ++i) {
      uint8_t b = 0;
      ASSERT_TRUE(p.txActive()) << r.what;
      ASSERT_TRUE(p.takeTx(b)) << r.what;
    }
    for (int i = 0; i < r.rxPut; ++i) {
      ASSERT_TRUE(p.rxActive()) << r.what;
      ASSERT_TRUE(p.putRx(0x42)) << r.what;
    }
    for (int read = 0; read < 2; ++read) {
      EXPECT_EQ(p.endTx(), r.endTx) << r.what << ", read " << read;
      EXPECT_EQ(p.txBufferEmpty(), r.txBufe) << r.what << ", read " << read;
      EXPECT_EQ(p.endRx(), r.endRx) << r.what << ", read " << read;
      EXPECT_EQ(p.rxBufferFull(), r.rxBuff) << r.what << ", read " << read;
    }
  }
}

TEST(Pdc, PtsrAndPtcrAreTheOnlyControlRegistersAndPtsrIsReadOnly) {
  Ram ram;
  Pdc p(ram);
  uint32_t v = 0;
  EXPECT_FALSE(p.read(0x28, v));
  EXPECT_FALSE(p.write(0x28, 1));
  EXPECT_FALSE(p.write(kPtsr, 0x101));
  EXPECT_EQ(reg(p, kPtsr), 0u);
}

TEST(Pdc, TransmitWalksTheCurrentBufferThenTheNextOne) {
  Ram ram;
  for (uint8_t i = 0; i < 8; ++i) ram.bytes[i] = static_cast<uint8_t>(0xA0 + i);
  Pdc p(ram);
  p.write(kTpr, kRam);
  p.write(kTcr, 2);
  p.write(kTnpr, kRam + 4);
  p.write(kTncr, 3);
  EXPECT_FALSE(p.txActive());  // not enabled yet
  p.write(kPtcr, 0x100);
  // byte taken, then the registers and the flags after it
  struct Step {
    uint8_t byte;
    uint32_t tpr, tcr, tncr;
    bool endTx, bufferEmpty;
  };
  const Step steps[] = {
      {0xA0, kRam + 1, 1, 3, false, false}, {0xA1, kRam + 4, 3, 0, false, false},  // chained at 0
      {0xA4, kRam + 5, 2, 0, false, false}, {0xA5, kRam + 6, 1, 0, false, false}, {0xA6, kRam + 7, 0, 0, true, true},
  };
  for (const Step& s : steps) {
    ASSERT_TRUE(p.txActive());
    uint8_t b = 0;
    ASSERT_TRUE(p.takeTx(b));
    EXPECT_EQ(b, s.byte);
    EXPECT_EQ(reg(p, kTpr), s.tpr);
    EXPECT_EQ(reg(p, kTcr), s.tcr);
    EXPECT_EQ(reg(p, kTncr), s.tncr);
    EXPECT_EQ(p.endTx(), s.endTx);
    EXPECT_EQ(p.txBufferEmpty(), s.bufferEmpty);
  }
  EXPECT_FALSE(p.txActive());
}

TEST(Pdc, ReceiveFillsTheCurrentBufferThenTheNextAndReportsBothFull) {
  Ram ram;
  Pdc p(ram);
  p.write(kRpr, kRam + 0x10);
  p.write(kRcr, 1);
  p.write(kRnpr, kRam + 0x20);
  p.write(kRncr, 2);
  p.write(kPtcr, 1);
  EXPECT_FALSE(p.endRx());
  ASSERT_TRUE(p.putRx(0x11));
  EXPECT_EQ(reg(p, kRpr), kRam + 0x20);  // chained
  EXPECT_EQ(reg(p, kRcr), 2u);
  EXPECT_FALSE(p.endRx());
  ASSERT_TRUE(p.putRx(0x22));
  ASSERT_TRUE(p.putRx(0x33));
  EXPECT_TRUE(p.endRx());
  EXPECT_TRUE(p.rxBufferFull());
  EXPECT_FALSE(p.rxActive());
  EXPECT_EQ(ram.bytes[0x10], 0x11);
  EXPECT_EQ(ram.bytes[0x20], 0x22);
  EXPECT_EQ(ram.bytes[0x21], 0x33);
  // A next buffer given while both are full starts at once (LEGO's Bluetooth receive hands buffers back so).
  p.write(kRnpr, kRam + 0x30);
  p.write(kRncr, 4);
  EXPECT_TRUE(p.rxActive());
  EXPECT_EQ(reg(p, kRpr), kRam + 0x30);
  EXPECT_FALSE(p.rxBufferFull());
}

TEST(Pdc, WordUnitsAdvanceThePointerByTheUnitAndCountOnePerUnit) {
  Ram ram;
  for (uint8_t i = 0; i < 8; ++i) ram.bytes[i] = static_cast<uint8_t>(i + 1);
  Pdc p(ram);
  p.write(kTpr, kRam);
  p.write(kTcr, 2);
  p.write(kPtcr, 0x100);
  uint32_t v = 0;
  ASSERT_TRUE(p.takeTxUnit(v, 2));
  EXPECT_EQ(v, 0x0201u);  // little-endian
  EXPECT_EQ(reg(p, kTpr), kRam + 2);
  EXPECT_EQ(reg(p, kTcr), 1u);
  ASSERT_TRUE(p.takeTxUnit(v, 4));
  EXPECT_EQ(v, 0x06050403u);
  EXPECT_EQ(reg(p, kTcr), 0u);
}

TEST(Pdc, APointerOutsideMemoryIsReportedNotFollowed) {
  Ram ram;
  Pdc p(ram);
  p.write(kTpr, 0x100000 - 1);
  p.write(kTcr, 1);
  p.write(kPtcr, 0x100);
  uint8_t b = 0;
  EXPECT_FALSE(p.takeTx(b));
  p.write(kRpr, 0x300000);
  p.write(kRcr, 1);
  p.write(kPtcr, 1);
  EXPECT_FALSE(p.putRx(1));
}

}  // namespace
}  // namespace nxtmap::emu::test
