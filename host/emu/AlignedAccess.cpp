#include "host/emu/AlignedAccess.hpp"

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
constexpr int kMmuDataLoad = 0, kMmuDataStore = 1;  // MMUAccessType

bool versionKnown() {
  unsigned major = 0, minor = 0;
  uc_version(&major, &minor);
  return major == 2 && minor == 0;
}

std::atomic<bool> g_allowed{true};
thread_local bool t_align = false;
thread_local bool t_seen = false;
thread_local UnalignedAccess t_access;

int aligned(int memop) {
  return t_align && (memop & kMoSize) != 0 && (memop & kMoAlign) == 0 ? memop | kMoAlign : memop;
}

// libunicorn without the function interposed: no code could be translated, so stop at once and say why
// (alignedAccessAvailable() keeps this path to Unicorn 2.0, which exports all three).
[[noreturn]] void missing(const char* symbol) {
  std::fprintf(stderr, "nxtmap emulator: libunicorn does not export %s; run with NXTMAP_EMU_LOAD_HOOK=1\n", symbol);
  std::abort();
}
}  // namespace

bool alignedAccessAvailable() {
  static const bool known = versionKnown();
  return known && g_allowed.load(std::memory_order_relaxed);
}

void setAlignedAccessAllowed(bool on) { g_allowed.store(on, std::memory_order_relaxed); }

void setAlignedAccess(bool on) {
  t_align = on;
  t_seen = false;
}

std::optional<UnalignedAccess> takeUnalignedAccess() {
  if (!t_seen) return std::nullopt;
  t_seen = false;
  return t_access;
}

}  // namespace nxtmap::emu

// Interposed over libunicorn's own definitions (the executable's definitions win: libunicorn calls them
// through its PLT/GOT, and the linker exports a definition a linked shared library also has).
extern "C" {
void tcg_gen_qemu_ld_i32_arm(void* s, void* val, void* addr, uintptr_t idx, int memop) {
  using Fn = void (*)(void*, void*, void*, uintptr_t, int);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "tcg_gen_qemu_ld_i32_arm"));
  if (real == nullptr) nxtmap::emu::missing("tcg_gen_qemu_ld_i32_arm");
  real(s, val, addr, idx, nxtmap::emu::aligned(memop));
}
void tcg_gen_qemu_st_i32_arm(void* s, void* val, void* addr, uintptr_t idx, int memop) {
  using Fn = void (*)(void*, void*, void*, uintptr_t, int);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "tcg_gen_qemu_st_i32_arm"));
  if (real == nullptr) nxtmap::emu::missing("tcg_gen_qemu_st_i32_arm");
  real(s, val, addr, idx, nxtmap::emu::aligned(memop));
}
void arm_cpu_do_unaligned_access_arm(void* cpu, uint64_t vaddr, int accessType, int mmuIdx, uintptr_t retaddr) {
  using Fn = void (*)(void*, uint64_t, int, int, uintptr_t);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "arm_cpu_do_unaligned_access_arm"));
  if (accessType == nxtmap::emu::kMmuDataLoad || accessType == nxtmap::emu::kMmuDataStore) {
    nxtmap::emu::t_seen = true;
    nxtmap::emu::t_access = {static_cast<uint32_t>(vaddr), accessType == nxtmap::emu::kMmuDataStore};
  }
  if (real == nullptr) nxtmap::emu::missing("arm_cpu_do_unaligned_access_arm");
  real(cpu, vaddr, accessType, mmuIdx, retaddr);  // raises the data abort; does not return
}
}
