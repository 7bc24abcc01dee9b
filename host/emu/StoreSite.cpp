#include "host/emu/StoreSite.hpp"

namespace nxtmap::emu {
namespace {

struct Decoded {
  bool store = false;        // a single-register store
  unsigned writes = 0;       // memory writes the instruction makes when it runs
  bool conditional = false;  // ARM condition other than always: it may make none
  uint32_t address = 0;
  unsigned bytes = 0;
  int rd = 0;
  int base = -1;
  uint32_t baseValue = 0;
};

bool readWord(const GuestMemory& m, uint32_t a, unsigned bytes, uint32_t& v) {
  v = 0;
  for (unsigned i = 0; i < bytes; ++i) {
    uint8_t b = 0;
    if (!m.readByte(a + i, b)) return false;
    v |= uint32_t{b} << (8 * i);
  }
  return true;
}

// ARM immediate shift of a register offset (LSL/LSR/ASR/ROR by 0..31; RRX cannot be computed: false).
bool shifted(uint32_t rm, unsigned type, unsigned amount, uint32_t& out) {
  switch (type) {
    case 0: out = rm << amount; return true;
    case 1: out = amount == 0 ? 0 : rm >> amount; return true;
    case 2: {
      const auto s = static_cast<int32_t>(rm);
      out = static_cast<uint32_t>(amount == 0 ? (s < 0 ? -1 : 0) : s >> amount);
      return true;
    }
    default:
      if (amount == 0) return false;
      out = (rm >> amount) | (rm << (32 - amount));
      return true;
  }
}

Decoded decodeArm(uint32_t insn, uint32_t pc, const std::array<uint32_t, 16>& r) {
  Decoded d;
  d.conditional = (insn >> 28) != 0xE;
  if ((insn & 0x0E100000) == 0x08000000) {  // STM
    d.writes = static_cast<unsigned>(__builtin_popcount(insn & 0xFFFF));
    return d;
  }
  if ((insn & 0x0FB00FF0) == 0x01000090) {  // SWP/SWPB
    d.writes = 1;
    return d;
  }
  const int rn = static_cast<int>((insn >> 16) & 15);
  d.rd = static_cast<int>((insn >> 12) & 15);
  const uint32_t base = rn == 15 ? pc + 8 : r[static_cast<size_t>(rn)];
  const bool p = (insn >> 24) & 1, u = (insn >> 23) & 1, w = (insn >> 21) & 1, load = (insn >> 20) & 1;
  uint32_t offset = 0;
  if ((insn & 0x0C000000) == 0x04000000 && !load) {  // STR/STRB
    if ((insn >> 25) & 1) {
      if (insn & 0x10) return d;  // media space, not a store
      if (!shifted(r[insn & 15], (insn >> 5) & 3, (insn >> 7) & 31, offset)) return d;
    } else {
      offset = insn & 0xFFF;
    }
    d.bytes = ((insn >> 22) & 1) ? 1 : 4;
  } else if ((insn & 0x0E0000F0) == 0x000000B0 && !load) {  // STRH
    offset = ((insn >> 22) & 1) ? (((insn >> 4) & 0xF0) | (insn & 0xF)) : r[insn & 15];
    d.bytes = 2;
  } else {
    return d;
  }
  const uint32_t moved = u ? base + offset : base - offset;
  d.address = p ? moved : base;
  if (!p || w) {
    d.base = rn;
    d.baseValue = moved;
  }
  d.store = d.rd != 15;
  d.writes = 1;
  return d;
}

Decoded decodeThumb(uint32_t insn, const std::array<uint32_t, 16>& r) {
  Decoded d;
  const auto reg = [&r](uint32_t i) { return r[i & 7]; };
  d.rd = static_cast<int>(insn & 7);
  const uint32_t imm5 = (insn >> 6) & 31;
  switch (insn & 0xF800) {
    case 0x6000: d.bytes = 4, d.address = reg(insn >> 3) + imm5 * 4; break;  // STR Rd, [Rn, #imm]
    case 0x7000: d.bytes = 1, d.address = reg(insn >> 3) + imm5; break;      // STRB
    case 0x8000: d.bytes = 2, d.address = reg(insn >> 3) + imm5 * 2; break;  // STRH
    case 0x9000:                                                             // STR Rd, [SP, #imm]
      d.rd = static_cast<int>((insn >> 8) & 7);
      d.bytes = 4;
      d.address = r[13] + (insn & 0xFF) * 4;
      break;
    case 0x5000: {  // register offset: STR 000, STRH 001, STRB 010
      const uint32_t op = (insn >> 9) & 7;
      if (op > 2) return d;
      d.bytes = op == 0 ? 4 : op == 1 ? 2 : 1;
      d.address = reg(insn >> 3) + reg(insn >> 6);
      break;
    }
    case 0xB000:  // PUSH {list[, LR]}
      if ((insn & 0x0600) == 0x0400) d.writes = static_cast<unsigned>(__builtin_popcount(insn & 0x1FF));
      return d;
    case 0xC000: d.writes = static_cast<unsigned>(__builtin_popcount(insn & 0xFF)); return d;  // STMIA
    default: return d;
  }
  d.store = true;
  d.writes = 1;
  return d;
}

}  // namespace

std::optional<StoreSite> findStoreSite(const GuestMemory& memory, uint32_t blockStart, uint32_t blockBytes, bool thumb,
                                       const std::array<uint32_t, 16>& regs, uint32_t address, unsigned bytes,
                                       uint32_t value, unsigned writeOrdinal) {
  const unsigned step = thumb ? 2 : 4;
  const uint32_t mask = bytes >= 4 ? 0xFFFFFFFFu : (1u << (8 * bytes)) - 1;
  std::optional<StoreSite> found;
  bool ambiguous = false;
  unsigned writesBefore = 0;
  bool counted = writeOrdinal != 0;  // the write count locates the store while no store before it is conditional
  for (uint32_t pc = blockStart; pc + step <= blockStart + blockBytes; pc += step) {
    uint32_t insn = 0;
    if (!readWord(memory, pc, step, insn)) return std::nullopt;
    const Decoded d = thumb ? decodeThumb(insn, regs) : decodeArm(insn, pc, regs);
    const bool matches = d.store && d.bytes == bytes && d.address == address &&
                         (regs[static_cast<size_t>(d.rd)] & mask) == (value & mask);
    if (counted && d.writes > 0 && writesBefore + 1 == writeOrdinal) {
      if (!matches) return std::nullopt;  // the count points elsewhere: the block is not what was decoded
      return StoreSite{pc, pc + step, d.base, d.baseValue};
    }
    if (counted && d.writes > 0 && d.conditional) counted = false;
    writesBefore += d.writes;
    if (!matches) continue;
    ambiguous = ambiguous || found.has_value();  // two stores could have made it: which one is unknown
    found = StoreSite{pc, pc + step, d.base, d.baseValue};
  }
  if (ambiguous) return std::nullopt;
  return found;
}

}  // namespace nxtmap::emu
