#include "host/emu/AccessBytes.hpp"

namespace nxtmap::emu {

unsigned loadBytes(uint32_t insn, bool thumb) {
  if (thumb) {
    const uint32_t h = insn & 0xFFFF;
    if ((h & 0xF000) == 0x5000) {  // register offset: op in bits 9..11
      switch ((h >> 9) & 7) {
        case 3: return 1;  // LDRSB
        case 4: return 4;  // LDR
        case 5: return 2;  // LDRH
        case 6: return 1;  // LDRB
        case 7: return 2;  // LDRSH
        default: return 0;
      }
    }
    switch (h & 0xF800) {
      case 0x4800: return 4;  // LDR pc-relative
      case 0x6800: return 4;  // LDR immediate
      case 0x7800: return 1;  // LDRB immediate
      case 0x8800: return 2;  // LDRH immediate
      case 0x9800: return 4;  // LDR sp-relative
      case 0xC800: return 4;  // LDMIA
      default: break;
    }
    return (h & 0xFE00) == 0xBC00 ? 4 : 0;  // POP
  }
  if ((insn & 0x0C100000) == 0x04100000) return (insn & (1u << 22)) ? 1 : 4;  // LDR, LDRB
  if ((insn & 0x0E100090) == 0x00100090 && (insn & 0x60) != 0)
    return ((insn >> 5) & 3) == 2 ? 1 : 2;                                    // LDRH, LDRSB, LDRSH
  if ((insn & 0x0E100000) == 0x08100000) return 4;                            // LDM
  if ((insn & 0x0FB00FF0) == 0x01000090) return (insn & (1u << 22)) ? 1 : 4;  // SWP, SWPB
  return 0;
}

unsigned storeBytes(uint32_t insn, bool thumb) {
  if (thumb) {
    const uint32_t h = insn & 0xFFFF;
    if ((h & 0xF000) == 0x5000) {  // register offset: op in bits 9..11
      switch ((h >> 9) & 7) {
        case 0: return 4;  // STR
        case 1: return 2;  // STRH
        case 2: return 1;  // STRB
        default: return 0;
      }
    }
    switch (h & 0xF800) {
      case 0x6000: return 4;  // STR immediate
      case 0x7000: return 1;  // STRB immediate
      case 0x8000: return 2;  // STRH immediate
      case 0x9000: return 4;  // STR sp-relative
      case 0xC000: return 4;  // STMIA
      default: break;
    }
    return (h & 0xFE00) == 0xB400 ? 4 : 0;  // PUSH
  }
  if ((insn & 0x0C100000) == 0x04000000) return (insn & (1u << 22)) ? 1 : 4;  // STR, STRB
  if ((insn & 0x0E1000F0) == 0x000000B0) return 2;                            // STRH
  if ((insn & 0x0E100000) == 0x08000000) return 4;                            // STM
  if ((insn & 0x0FB00FF0) == 0x01000090) return (insn & (1u << 22)) ? 1 : 4;  // SWP, SWPB
  return 0;
}

}  // namespace nxtmap::emu
