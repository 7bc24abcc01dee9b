// The USB device port of a brick with no cable, at register level (AT91SAM7S datasheet, UDP chapter): the
// set-up registers keep what is written (within their fields), FADDR resets with FEN set, and since no bus
// event ever comes ISR, FRM_NUM and the FIFOs read 0.
#include "host/emu/Udp.hpp"

#include <gtest/gtest.h>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kFrmNum = 0x00, kGlbStat = 0x04, kFaddr = 0x08, kIer = 0x10, kIdr = 0x14, kImr = 0x18, kIsr = 0x1C,
                   kIcr = 0x20, kRstEp = 0x28, kCsr0 = 0x30, kFdr0 = 0x50, kTxvc = 0x74;

uint32_t reg(Udp& u, uint32_t off) {
  uint32_t v = 0xDEADBEEF;
  EXPECT_TRUE(u.read(off, v)) << off;
  return v;
}

TEST(Udp, ResetValues) {
  Udp u;
  struct Row {
    uint32_t off, value;
  };
  const Row rows[] = {{kFrmNum, 0}, {kGlbStat, 0}, {kFaddr, 0x100}, {kImr, 0},      {kIsr, 0},
                      {kRstEp, 0},  {kCsr0, 0},    {kCsr0 + 12, 0}, {kFdr0 + 4, 0}, {kTxvc, 0}};
  for (const Row& r : rows) EXPECT_EQ(reg(u, r.off), r.value) << std::hex << r.off;
}

TEST(Udp, WritesKeepTheirFields) {
  struct Row {
    const char* what;
    uint32_t off, value, expect;
  };
  const Row rows[] = {
      {"GLB_STAT FADDEN, CONFG, ESR, RSMINPR, RMWUPE", kGlbStat, 0xFFFFFFFF, 0x1F},
      {"FADDR FADD and FEN", kFaddr, 0xFFFFFFFF, 0x17F},
      {"RST_EP endpoints 0..3", kRstEp, 0xFFFFFFFF, 0xF},
      {"CSR1 EPEDS, EPTYPE, DIR, DTGLE and the control bits", kCsr0 + 4, 0xFFFFFFFF, 0x8F87},
      {"TXVC TXVDIS and PUON", kTxvc, 0xFFFFFFFF, 0x300},
  };
  for (const Row& r : rows) {
    Udp u;
    ASSERT_TRUE(u.write(r.off, r.value)) << r.what;
    const uint32_t readOff = r.off;
    EXPECT_EQ(reg(u, readOff), r.expect) << r.what;
  }
}

TEST(Udp, InterruptMaskButNoEventEver) {
  Udp u;
  ASSERT_TRUE(u.write(kIer, 0x3F0F));
  ASSERT_TRUE(u.write(kIdr, 0x000F));
  EXPECT_EQ(reg(u, kImr), 0x3F00u);
  ASSERT_TRUE(u.write(kIcr, 0xFFFFFFFF));
  ASSERT_TRUE(u.write(kFdr0, 0x12));     // into a FIFO no host reads
  ASSERT_TRUE(u.write(kTxvc, 1u << 9));  // pull-up on: still no host
  EXPECT_EQ(reg(u, kIsr), 0u);
  EXPECT_EQ(reg(u, kFrmNum), 0u);
  EXPECT_EQ(reg(u, kFdr0), 0u);
  EXPECT_EQ(u.nextEventAt(), kNever);
  EXPECT_FALSE(u.writeReplans(kIer));
}

TEST(Udp, RegistersOutsideTheMapAreRefused) {
  Udp u;
  uint32_t v = 0;
  EXPECT_FALSE(u.read(0x60, v));
  EXPECT_FALSE(u.write(kIsr, 1));  // ISR is read-only
  EXPECT_FALSE(u.write(kFrmNum, 1));
}

}  // namespace
}  // namespace nxtmap::emu::test
