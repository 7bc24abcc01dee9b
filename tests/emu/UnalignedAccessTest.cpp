// Unaligned loads and stores stop the run with an Unaligned fault at the instruction, before it runs: caught
// by Unicorn's translated code (AlignedAccess), or by a hook on every access where Unicorn cannot. One
// instruction per row, ARM and Thumb, in a raw flash image; byte accesses never fault (ARMv4T).
#include "../support/TempDir.hpp"
#include "host/emu/AccessBytes.hpp"
#include "host/emu/AlignedAccess.hpp"
#include "host/emu/Machine.hpp"
#include "tests/emu/EmuTestSupport.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

struct Row {
  const char* what;
  bool thumb;
  uint32_t insn;      // the instruction under test: r0 = base, r1 = data register, r2 = 0
  uint32_t base;      // its address (RAM)
  const char* fault;  // the fault's text, nullptr = runs without a fault
};

// Reset at 0 (the flash mirror): r0 = base, then the instruction at 0x04 (ARM) or 0x0C (Thumb), then a loop.
std::vector<uint32_t> program(const Row& r) {
  if (!r.thumb) return {0xE59F0004, r.insn, 0xEAFFFFFE, r.base};  // ldr r0, [pc, #4]; insn; b .
  // ldr r0, [pc, #8]; add r3, pc, #1; bx r3; insn + b . (Thumb)
  return {0xE59F0008, 0xE28F3001, 0xE12FFF13, 0xE7FE0000 | r.insn, r.base};
}

TEST(UnalignedAccess, StopsAtTheLoadOrStoreWithItsAddressAndSize) {
  const Row rows[] = {
      {"ARM LDR", false, 0xE5901000, 0x200101, "read of 4 bytes"},
      {"ARM LDR, word-aligned", false, 0xE5901000, 0x200104, nullptr},
      {"ARM LDR, halfword-aligned", false, 0xE5901000, 0x200102, "read of 4 bytes"},
      {"ARM LDRH", false, 0xE1D010B0, 0x200103, "read of 2 bytes"},
      {"ARM LDRH, aligned", false, 0xE1D010B0, 0x200102, nullptr},
      {"ARM LDRSH", false, 0xE1D010F0, 0x200101, "read of 2 bytes"},
      {"ARM LDRB", false, 0xE5D01000, 0x200101, nullptr},
      {"ARM LDM, unaligned base", false, 0xE8900006, 0x200102, "read of 4 bytes"},
      {"ARM STR", false, 0xE5801000, 0x200101, "write of 4 bytes"},
      {"ARM STRH", false, 0xE1C010B0, 0x200101, "write of 2 bytes"},
      {"ARM STRB", false, 0xE5C01000, 0x200101, nullptr},
      {"ARM STM, unaligned base", false, 0xE8800006, 0x200102, "write of 4 bytes"},
      {"Thumb LDR", true, 0x6801, 0x200102, "read of 4 bytes"},
      {"Thumb LDR, aligned", true, 0x6801, 0x200100, nullptr},
      {"Thumb LDR register offset", true, 0x5881, 0x200103, "read of 4 bytes"},
      {"Thumb LDRH", true, 0x8801, 0x200101, "read of 2 bytes"},
      {"Thumb LDRSH register offset", true, 0x5E81, 0x200101, "read of 2 bytes"},
      {"Thumb LDRB", true, 0x7801, 0x200103, nullptr},
      {"Thumb LDMIA", true, 0xC802, 0x200101, "read of 4 bytes"},
      {"Thumb STR", true, 0x6001, 0x200102, "write of 4 bytes"},
      {"Thumb STRH", true, 0x8001, 0x200101, "write of 2 bytes"},
      {"Thumb STRH register offset", true, 0x5281, 0x200103, "write of 2 bytes"},
      {"Thumb STRB", true, 0x7001, 0x200103, nullptr},
      {"Thumb STMIA", true, 0xC002, 0x200102, "write of 4 bytes"},
      {"Thumb STR, aligned", true, 0x6001, 0x200104, nullptr},
  };
  nxtmap::test::TempDir dir("unaligned");
  // Checked by Unicorn where it can (the default), and by the hook on every access (another Unicorn).
  for (const bool unicornChecks : {true, false})
    for (const Row& r : rows) {
      SCOPED_TRACE(std::string(r.what) + (unicornChecks ? ", Unicorn checks" : ", hook on every access"));
      setAlignedAccessAllowed(unicornChecks);
      const std::string path = dir.path("probe.bin");
      const ElfLoad l = nxtmap::emu::test::loadWords(path, program(r));
      ASSERT_TRUE(l.image) << l.error;
      Machine m(*l.image, MachineOptions{});
      setAlignedAccessAllowed(true);
      const bool ok = m.run(200);
      if (!r.fault) {
        EXPECT_TRUE(ok) << m.fault().describe();
        continue;
      }
      ASSERT_FALSE(ok);
      EXPECT_EQ(m.fault().kind, FaultKind::Unaligned) << m.fault().describe();
      EXPECT_EQ(m.fault().address, r.base);
      // An access Unicorn checks stops at itself; a hook may see the PC of its block's start (Unicorn 2.0.1
      // syncs no PC for it), here the reset vector in ARM state.
      const uint32_t at = r.thumb ? 0x0Cu : 0x04u;
      if (unicornChecks)
        EXPECT_EQ(m.fault().pc, at);
      else
        EXPECT_LE(m.fault().pc, at);
      EXPECT_EQ(m.fault().what, r.fault);
    }
}

TEST(UnalignedAccess, SwitchedOffAnUnalignedLoadRuns) {
  const Row r{"ARM LDR", false, 0xE5901000, 0x200101, nullptr};
  nxtmap::test::TempDir dir("unaligned_off");
  const std::string path = dir.path("probe.bin");
  const ElfLoad l = nxtmap::emu::test::loadWords(path, program(r));
  ASSERT_TRUE(l.image) << l.error;
  MachineOptions o;
  o.checkAlignment = false;
  Machine m(*l.image, o);
  EXPECT_TRUE(m.run(200)) << m.fault().describe();
}

TEST(UnalignedAccess, LoadSizeFromTheEncoding) {
  struct Case {
    uint32_t insn;
    bool thumb;
    unsigned bytes;
  };
  const Case cases[] = {
      {0xE5901000, false, 4}, {0xE5D01000, false, 1}, {0xE1D010B0, false, 2}, {0xE1D010D0, false, 1},
      {0xE1D010F0, false, 2}, {0xE8BD8000, false, 4}, {0xE1001091, false, 4}, {0xE1401091, false, 1},
      {0xE5801000, false, 0}, {0xE0811002, false, 0}, {0x6801, true, 4},      {0x8801, true, 2},
      {0x7801, true, 1},      {0x5881, true, 4},      {0x5A81, true, 2},      {0x5C81, true, 1},
      {0x5681, true, 1},      {0x5E81, true, 2},      {0x4801, true, 4},      {0x9801, true, 4},
      {0xBC02, true, 4},      {0xC802, true, 4},      {0x6001, true, 0},      {0x1841, true, 0},
  };
  for (const Case& c : cases) EXPECT_EQ(loadBytes(c.insn, c.thumb), c.bytes) << std::hex << c.insn;
}

TEST(UnalignedAccess, StoreSizeFromTheEncoding) {
  struct Case {
    uint32_t insn;
    bool thumb;
    unsigned bytes;
  };
  const Case cases[] = {
      {0xE5801000, false, 4}, {0xE5C01000, false, 1}, {0xE1C010B0, false, 2}, {0xE18010B2, false, 2},
      {0xE92D4010, false, 4}, {0xE8800006, false, 4}, {0xE1001091, false, 4}, {0xE1401091, false, 1},
      {0xE5901000, false, 0}, {0xE1D010B0, false, 0}, {0xE0811002, false, 0}, {0x6001, true, 4},
      {0x8001, true, 2},      {0x7001, true, 1},      {0x5081, true, 4},      {0x5281, true, 2},
      {0x5481, true, 1},      {0x9001, true, 4},      {0xB510, true, 4},      {0xC002, true, 4},
      {0x6801, true, 0},      {0x5E81, true, 0},      {0xBD10, true, 0},      {0x1841, true, 0},
  };
  for (const Case& c : cases) EXPECT_EQ(storeBytes(c.insn, c.thumb), c.bytes) << std::hex << c.insn;
}

}  // namespace
}  // namespace nxtmap::emu::test
