// The AIC at register level (AT91SAM7S datasheet, AIC chapter): IVR acknowledges the highest-priority
// pending source and EOICR ends it; level and edge sources; ISCR/ICCR; protect mode (DCR.PROT: an IVR
// read changes nothing, the IVR write acknowledges) and the general mask (DCR.GMSK: no nIRQ).
#include "host/emu/Aic.hpp"

#include <gtest/gtest.h>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kIvr = 0x100, kIsr = 0x108, kIpr = 0x10C, kCisr = 0x114, kIecr = 0x120, kIccr = 0x128, kIscr = 0x12C,
                   kEoicr = 0x130, kSpu = 0x134, kDcr = 0x138;
constexpr uint32_t smr(int id) { return 4 * static_cast<uint32_t>(id); }
constexpr uint32_t svr(int id) { return 0x80 + 4 * static_cast<uint32_t>(id); }
constexpr uint32_t kEdge = 1u << 5;

struct Rig {
  Aic aic;
  bool line7 = false, line9 = false;
  Rig() {
    aic.connect(7, [this] { return line7; });
    aic.connect(9, [this] { return line9; });
    aic.write(smr(7), 2);  // level, priority 2
    aic.write(smr(9), 5);  // level, priority 5
    aic.write(smr(10), kEdge | 1);
    for (int id : {7, 9, 10}) aic.write(svr(id), 0x1000u + static_cast<uint32_t>(id));
    aic.write(kSpu, 0xDEAD);
    aic.write(kIecr, (1u << 7) | (1u << 9) | (1u << 10));
  }
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    EXPECT_TRUE(aic.read(off, v)) << off;
    return v;
  }
  bool nirq() {
    aic.sample();
    return aic.irqAsserted();
  }
};

TEST(Aic, IvrAcknowledgesTheHighestPriorityAndNestsByPriority) {
  Rig g;
  EXPECT_EQ(g.reg(kIvr), 0xDEADu);  // nothing pending: the spurious vector
  g.line7 = g.line9 = true;
  EXPECT_EQ(g.reg(kIpr), (1u << 7) | (1u << 9));
  EXPECT_TRUE(g.nirq());
  EXPECT_EQ(g.reg(kIvr), 0x1009u);  // priority 5 first
  EXPECT_EQ(g.reg(kIsr), 9u);
  EXPECT_FALSE(g.nirq());  // 7 (priority 2) cannot interrupt 9
  g.line9 = false;
  g.aic.write(kEoicr, 0);
  EXPECT_TRUE(g.nirq());
  EXPECT_EQ(g.reg(kIvr), 0x1007u);
  g.aic.write(kEoicr, 0);
}

TEST(Aic, EdgeSourcesLatchAndTheAcknowledgeClearsThem) {
  Rig g;
  g.aic.write(kIscr, 1u << 10);  // the software interrupt
  EXPECT_EQ(g.reg(kIpr), 1u << 10);
  EXPECT_EQ(g.reg(kIvr), 0x100Au);
  EXPECT_EQ(g.reg(kIpr), 0u);  // edge: cleared by the acknowledge
  g.aic.write(kEoicr, 0);
  g.aic.write(kIscr, 1u << 10);
  g.aic.write(kIccr, 1u << 10);
  EXPECT_EQ(g.reg(kIpr), 0u);
}

TEST(Aic, ProtectModeIvrReadChangesNothingUntilTheIvrWrite) {
  struct Row {
    const char* what;
    uint32_t dcr;
    bool writeIvr;
    uint32_t isrAfter, iprAfter;
    bool nirqAfter;
    uint64_t taken;
  };
  const Row rows[] = {
      {"normal mode: the read acknowledges", 0, false, 10, 0, false, 1},
      {"protect mode: the read alone changes nothing", 1, false, 0, 1u << 10, true, 0},
      {"protect mode: the write acknowledges", 1, true, 10, 0, false, 1},
      {"normal mode: an IVR write does nothing more", 0, true, 10, 0, false, 1},
  };
  for (const Row& r : rows) {
    Rig g;
    g.aic.write(kDcr, r.dcr);
    EXPECT_EQ(g.reg(kDcr), r.dcr) << r.what;
    g.aic.write(kIscr, 1u << 10);
    EXPECT_EQ(g.reg(kIvr), 0x100Au) << r.what;                    // the vector either way
    EXPECT_EQ(g.reg(kIvr), r.dcr ? 0x100Au : 0xDEADu) << r.what;  // a second read (a debugger's) sees the same
    if (r.writeIvr) g.aic.write(kIvr, 0);
    EXPECT_EQ(g.reg(kIsr), r.isrAfter) << r.what;
    EXPECT_EQ(g.reg(kIpr), r.iprAfter) << r.what;
    EXPECT_EQ(g.nirq(), r.nirqAfter) << r.what;
    EXPECT_EQ(g.aic.irqsTaken(), r.taken) << r.what;
  }
}

TEST(Aic, GeneralMaskHoldsNirqAndTheWakeUp) {
  Rig g;
  g.line9 = true;
  g.aic.write(kDcr, 2);
  g.aic.sample();
  EXPECT_FALSE(g.aic.irqAsserted());
  EXPECT_FALSE(g.aic.wakeAsserted());
  EXPECT_EQ(g.reg(kCisr), 0u);
  EXPECT_EQ(g.reg(kIpr), 1u << 9);  // still pending
  g.aic.write(kDcr, 0);
  EXPECT_TRUE(g.nirq());
  EXPECT_TRUE(g.aic.wakeAsserted());
  EXPECT_EQ(g.reg(kCisr), 2u);
  EXPECT_TRUE(g.aic.writeReplans(kDcr));
}

TEST(Aic, SourceModeKeepsPriorityAndType) {
  Rig g;
  g.aic.write(smr(4), 0xFFFFFFFF);
  EXPECT_EQ(g.reg(smr(4)), 0x67u);  // SRCTYPE b5-6, PRIOR b0-2
  g.aic.write(kDcr, 0xFF);
  EXPECT_EQ(g.reg(kDcr), 3u);
}

}  // namespace
}  // namespace nxtmap::emu::test
