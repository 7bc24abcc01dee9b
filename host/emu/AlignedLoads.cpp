#include "host/emu/AlignedLoads.hpp"

#include <unicorn/unicorn.h>

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace nxtmap::emu {
namespace {
// QEMU 5.0 MemOp (include/exec/memop.h): bits 0..1 the size log2, MO_AMASK bits 4..6; MO_ALIGN == MO_AMASK
// asks for alignment to the access size.
constexpr int kMoSize = 0x3;
constexpr int kMoAlign = 0x70;
constexpr int kMmuDataLoad = 0;  // MMUAccessType MMU_DATA_LOAD

bool versionKnown() {
  unsigned major = 0, minor = 0;
  uc_version(&major, &minor);
  return major == 2 && minor == 0;
}

std::atomic<bool> g_allowed{true};
thread_local bool t_align = false;
thread_local bool t_seen = false;
thread_local uint32_t t_address = 0;
}  // namespace

bool alignedLoadsAvailable() {
  static const bool known = versionKnown();
  return known && g_allowed.load(std::memory_order_relaxed);
}

void setAlignedLoadsAllowed(bool on) { g_allowed.store(on, std::memory_order_relaxed); }

void setAlignedLoads(bool on) {
  t_align = on;
  t_seen = false;
}

std::optional<uint32_t> takeUnalignedLoad() {
  if (!t_seen) return std::nullopt;
  t_seen = false;
  return t_address;
}

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

// libunicorn without the function interposed: no code could be translated, so stop at once and say why
// (alignedLoadsAvailable() keeps this path to Unicorn 2.0, which exports both).
namespace {
[[noreturn]] void missing(const char* symbol) {
  std::fprintf(stderr, "nxtmap emulator: libunicorn does not export %s; run with NXTMAP_EMU_LOAD_HOOK=1\n", symbol);
  std::abort();
}
}  // namespace

}  // namespace nxtmap::emu

// Interposed over libunicorn's own definitions (the executable's definitions win: libunicorn calls both
// through its PLT/GOT, and the linker exports a definition a linked shared library also has).
extern "C" {
void tcg_gen_qemu_ld_i32_arm(void* s, void* val, void* addr, uintptr_t idx, int memop) {
  using Fn = void (*)(void*, void*, void*, uintptr_t, int);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "tcg_gen_qemu_ld_i32_arm"));
  using nxtmap::emu::kMoAlign;
  if (nxtmap::emu::t_align && (memop & nxtmap::emu::kMoSize) != 0 && (memop & kMoAlign) == 0) memop |= kMoAlign;
  if (real == nullptr) nxtmap::emu::missing("tcg_gen_qemu_ld_i32_arm");
  real(s, val, addr, idx, memop);
}
void arm_cpu_do_unaligned_access_arm(void* cpu, uint64_t vaddr, int accessType, int mmuIdx, uintptr_t retaddr) {
  using Fn = void (*)(void*, uint64_t, int, int, uintptr_t);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "arm_cpu_do_unaligned_access_arm"));
  if (accessType == nxtmap::emu::kMmuDataLoad) {
    nxtmap::emu::t_seen = true;
    nxtmap::emu::t_address = static_cast<uint32_t>(vaddr);
  }
  if (real == nullptr) nxtmap::emu::missing("arm_cpu_do_unaligned_access_arm");
  real(cpu, vaddr, accessType, mmuIdx, retaddr);  // raises the data abort; does not return
}
}
