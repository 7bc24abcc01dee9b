// The stack guard: a store in [guardLow, stackLimit) stops the run with a StackOverflow fault at its address;
// loads there and stores around it run. One store per row in a raw flash image, with a guard whose ends are
// not on page edges (read-only pages in the middle, painted bytes checked after the fact at the ends) and one
// inside a single page; every row both ways (no memory hook: StackGuard; a hook on every access).
#include "../support/TempDir.hpp"
#include "host/emu/AlignedAccess.hpp"
#include "host/emu/Machine.hpp"
#include "tests/emu/EmuTestSupport.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kData = 0x11223344;

struct Row {
  const char* what;
  uint32_t insn;     // ARM, r0 = address, r1 = kData, r2 = 0
  uint32_t address;  // of the store
  unsigned bytes;    // it writes (all of them when it runs)
  bool fault;        // a stack overflow
};

// Reset at 0 (the flash mirror): r0 = address, r1 = kData, the store, then a loop.
std::vector<uint32_t> program(const Row& r) { return {0xE59F0008, 0xE59F1008, r.insn, 0xEAFFFFFE, r.address, kData}; }

constexpr uint32_t kStr = 0xE5801000, kStrh = 0xE1C010B0, kStrb = 0xE5C01000, kStm = 0xE8800006, kLdr = 0xE5901000;

void runRows(const char* name, uint32_t low, uint32_t limit, const std::vector<Row>& rows) {
  nxtmap::test::TempDir dir(name);
  char limitText[32];
  std::snprintf(limitText, sizeof limitText, "0x%08x", static_cast<unsigned>(limit));
  for (const bool hook : {false, true})
    for (const Row& r : rows) {
      SCOPED_TRACE(std::string(r.what) + (hook ? ", hook on every access" : ", pages"));
      const std::string path = dir.path("probe.bin");
      const ElfLoad l = nxtmap::emu::test::loadWords(path, program(r));
      ASSERT_TRUE(l.image) << l.error;
      MachineOptions o;
      o.guardLow = low;
      o.stackLimit = limit;
      setAlignedAccessAllowed(!hook);
      Machine m(*l.image, o);
      setAlignedAccessAllowed(true);
      const bool ok = m.run(200);
      if (!r.fault) {
        ASSERT_TRUE(ok) << m.fault().describe();
        if (r.insn == kLdr) continue;
        for (unsigned i = 0; i < r.bytes; ++i) {
          uint8_t b = 0;
          ASSERT_TRUE(m.readByte(r.address + i, b));
          EXPECT_EQ(b, i < 4 ? static_cast<uint8_t>(kData >> (8 * i)) : 0) << i;  // STM: r1, then r2 = 0
        }
        continue;
      }
      ASSERT_FALSE(ok);
      EXPECT_EQ(m.fault().kind, FaultKind::StackOverflow) << m.fault().describe();
      EXPECT_EQ(m.fault().address & ~3u, r.address & ~3u) << m.fault().describe();
      EXPECT_GE(m.fault().address, low);
      EXPECT_EQ(m.fault().what.rfind(std::string("write below the stack limit ") + limitText, 0), 0u) << m.fault().what;
    }
}

TEST(StackGuard, AStoreInTheGuardStopsTheRunWithItsAddress) {
  // Pages of 1 KiB: [0x200123, 0x200400) painted, [0x200400, 0x200800) read-only, [0x200800, 0x200a66) painted.
  runRows("stack_guard", 0x200123, 0x200A66,
          {
              {"STR below the guard", kStr, 0x20011C, 4, false},
              {"STRB just below the guard", kStrb, 0x200122, 1, false},
              {"STRB on the guard's first byte", kStrb, 0x200123, 1, true},
              {"STR in the painted bytes by .bss", kStr, 0x200200, 4, true},
              {"STR on the first read-only page", kStr, 0x200400, 4, true},
              {"STRH in a read-only page", kStrh, 0x200602, 2, true},
              {"STM across the last read-only page's end", kStm, 0x2007FC, 8, true},
              {"STR in the painted bytes by the stacks", kStr, 0x200900, 4, true},
              {"STRB on the guard's last byte", kStrb, 0x200A65, 1, true},
              {"STRH at the stack limit", kStrh, 0x200A66, 2, false},
              {"STR above the stack limit", kStr, 0x200A68, 4, false},
              {"STM above the stack limit", kStm, 0x200F00, 8, false},
              {"LDR from a read-only page", kLdr, 0x200500, 4, false},
              {"LDR from the painted bytes", kLdr, 0x200A60, 4, false},
          });
}

TEST(StackGuard, AGuardInsideOnePageIsAllPainted) {
  runRows("stack_guard_page", 0x200F10, 0x200F40,
          {
              {"STRB below", kStrb, 0x200F0F, 1, false},
              {"STRB first byte", kStrb, 0x200F10, 1, true},
              {"STR last word", kStr, 0x200F3C, 4, true},
              {"STR at the limit", kStr, 0x200F40, 4, false},
          });
}

}  // namespace
}  // namespace nxtmap::emu::test
