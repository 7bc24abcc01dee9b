// StoreSite: which instruction of a block made a store, from the ARMv4T encodings (ARM ARM A4/A5, Thumb A7).
#include "host/emu/StoreSite.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCode = 0x200000;

// A block of code at kCode, little-endian halfwords or words.
class Code : public GuestMemory {
 public:
  Code(std::vector<uint32_t> insns, unsigned bytes) {
    for (uint32_t i : insns)
      for (unsigned b = 0; b < bytes; ++b) mem_.push_back(static_cast<uint8_t>(i >> (8 * b)));
  }
  uint32_t size() const { return static_cast<uint32_t>(mem_.size()); }
  bool readByte(uint32_t a, uint8_t& v) const override {
    if (a < kCode || a - kCode >= mem_.size()) return false;
    v = mem_[a - kCode];
    return true;
  }
  bool writeByte(uint32_t, uint8_t) override { return false; }

 private:
  std::vector<uint8_t> mem_;
};

struct Row {
  const char* what;
  bool thumb;
  std::vector<uint32_t> insns;
  uint32_t address;
  unsigned bytes;
  uint32_t value;
  unsigned ordinal;
  int site;  // index of the instruction found, -1 none
  int base;
  uint32_t baseValue;
};

TEST(StoreSite, FindsTheStoreFromItsAddressValueAndWriteCount) {
  // r0 = 0xFFFB8000, r1 = 0x104, r2 = 0xFFFB8024, r3 = 4, sp = 0x20F000
  std::array<uint32_t, 16> r{0xFFFB8000u, 0x104u, 0xFFFB8024u, 4u};
  r[13] = 0x20F000;
  const Row rows[] = {
      {"thumb str r1,[r0,#0x24]", true, {0x4600, 0x6241}, 0xFFFB8024, 4, 0x104, 0, 1, -1, 0},
      {"thumb strb r1,[r0,#4]", true, {0x7101}, 0xFFFB8004, 1, 0x04, 0, 0, -1, 0},
      {"thumb strh r1,[r0,#2]", true, {0x8041}, 0xFFFB8002, 2, 0x104, 0, 0, -1, 0},
      {"thumb str r1,[r0,r3]", true, {0x50C1}, 0xFFFB8004, 4, 0x104, 0, 0, -1, 0},
      {"thumb str r1,[sp,#8]", true, {0x9102}, 0x20F008, 4, 0x104, 0, 0, -1, 0},
      {"thumb: wrong value", true, {0x6241}, 0xFFFB8024, 4, 0x105, 0, -1, -1, 0},
      {"thumb str r1,[r2] twice, no count", true, {0x6011, 0x6011}, 0xFFFB8024, 4, 0x104, 0, -1, -1, 0},
      {"thumb str r1,[r2] twice, second write", true, {0x6011, 0x6011}, 0xFFFB8024, 4, 0x104, 2, 1, -1, 0},
      {"thumb push then str: push counts its writes", true, {0xB403, 0x6011}, 0xFFFB8024, 4, 0x104, 3, 1, -1, 0},
      {"thumb stmia is never a site", true, {0xC002}, 0xFFFB8000, 4, 0x104, 1, -1, -1, 0},
      {"arm str r1,[r0,#0x24]", false, {0xE5801024}, 0xFFFB8024, 4, 0x104, 0, 0, -1, 0},
      {"arm str r1,[r0,#0x24]! writes back", false, {0xE5A01024}, 0xFFFB8024, 4, 0x104, 0, 0, 0, 0xFFFB8024},
      {"arm str r1,[r0],#4 post-indexed", false, {0xE4801004}, 0xFFFB8000, 4, 0x104, 0, 0, 0, 0xFFFB8004},
      {"arm str r1,[r0,-r3,lsl #1]", false, {0xE7001083}, 0xFFFB7FF8, 4, 0x104, 0, 0, -1, 0},
      {"arm strh r1,[r0,#0x24]", false, {0xE1C012B4}, 0xFFFB8024, 2, 0x104, 0, 0, -1, 0},
      {"arm stmia r0,{r1} is never a site", false, {0xE8800002}, 0xFFFB8000, 4, 0x104, 1, -1, -1, 0},
  };
  for (const Row& row : rows) {
    const Code code(row.insns, row.thumb ? 2 : 4);
    const auto s =
        findStoreSite(code, kCode, code.size(), row.thumb, r, row.address, row.bytes, row.value, row.ordinal);
    if (row.site < 0) {
      EXPECT_FALSE(s) << row.what;
      continue;
    }
    ASSERT_TRUE(s) << row.what;
    const uint32_t step = row.thumb ? 2 : 4;
    EXPECT_EQ(s->pc, kCode + step * static_cast<uint32_t>(row.site)) << row.what;
    EXPECT_EQ(s->next, s->pc + step) << row.what;
    EXPECT_EQ(s->base, row.base) << row.what;
    if (row.base >= 0) {
      EXPECT_EQ(s->baseValue, row.baseValue) << row.what;
    }
  }
}

}  // namespace
}  // namespace nxtmap::emu::test
