#include "host/emu/DirectStores.hpp"

#include "host/emu/UnicornFastPath.hpp"

#include <unicorn/unicorn.h>

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

namespace nxtmap::emu {
namespace {
bool versionKnown() {
  unsigned major = 0, minor = 0;
  uc_version(&major, &minor);
  return major == 2 && minor == 0;
}

thread_local uint32_t t_begin = 0, t_end = 0;
thread_local void** t_cpuSlot = nullptr;
thread_local uintptr_t t_storeReturn = 0;  // the slow-path store in progress: its return address, 0 none

template <typename Fn>
Fn real(const char* name) {
  return reinterpret_cast<Fn>(dlsym(RTLD_NEXT, name));
}

// A function the interposers forward to: libunicorn without it cannot run any code, so stop at once and say
// why (only Unicorn 2.0.x is known to export them all).
template <typename Fn>
Fn required(const char* name) {
  const auto fn = real<Fn>(name);
  if (fn == nullptr) {
    std::fprintf(stderr, "nxtmap emulator: libunicorn does not export %s (Unicorn 2.0.x is needed)\n", name);
    std::abort();
  }
  return fn;
}
}  // namespace

bool directStoresAvailable() {
  static const bool known = versionKnown();
  return known && unicornFastStores();
}

void setDirectRamStores(uint32_t begin, uint32_t end) {
  t_begin = begin;
  t_end = end;
}

void setCpuSlot(void** slot) {
  t_cpuSlot = slot;
  t_storeReturn = 0;
}

void flushTlb(void* cpu) {
  using Fn = void (*)(void*);
  static const auto flush = real<Fn>("tlb_flush_arm");
  if (cpu != nullptr && flush != nullptr) flush(cpu);
}

bool restoreStorePc(void* cpu) {
  using Fn = bool (*)(void*, uintptr_t, bool);
  static const auto restore = real<Fn>("cpu_restore_state_arm");
  return cpu != nullptr && t_storeReturn != 0 && restore != nullptr && restore(cpu, t_storeReturn, false);
}

}  // namespace nxtmap::emu

// Interposed over libunicorn's own definitions (the executable's definitions win: libunicorn calls them
// through its PLT, and the translated code reaches the store helpers through a table relocated against them).
// Signatures as in QEMU 5.0 for a 32-bit target (target_ulong 32 bits, MemTxAttrs 32 bits by value).
extern "C" {
void tlb_set_page_with_attrs_arm(void* cpu, uint32_t vaddr, uint64_t paddr, uint32_t attrs, int prot, int mmuIdx,
                                 uint32_t size) {
  using Fn = void (*)(void*, uint32_t, uint64_t, uint32_t, int, int, uint32_t);
  using Dirty = void (*)(void*, uint32_t);
  static const auto fill = nxtmap::emu::required<Fn>("tlb_set_page_with_attrs_arm");
  static const auto dirty = nxtmap::emu::real<Dirty>("tlb_set_dirty_arm");
  fill(cpu, vaddr, paddr, attrs, prot, mmuIdx, size);
  if (nxtmap::emu::t_cpuSlot != nullptr && *nxtmap::emu::t_cpuSlot == nullptr) *nxtmap::emu::t_cpuSlot = cpu;
  if (vaddr >= nxtmap::emu::t_begin && vaddr < nxtmap::emu::t_end && dirty != nullptr) dirty(cpu, vaddr);
}
void helper_ret_stb_mmu_arm(void* env, uint32_t addr, uint8_t val, uint32_t oi, uintptr_t retaddr) {
  using Fn = void (*)(void*, uint32_t, uint8_t, uint32_t, uintptr_t);
  static const auto store = nxtmap::emu::required<Fn>("helper_ret_stb_mmu_arm");
  nxtmap::emu::t_storeReturn = retaddr;
  store(env, addr, val, oi, retaddr);
  nxtmap::emu::t_storeReturn = 0;
}
void helper_le_stw_mmu_arm(void* env, uint32_t addr, uint16_t val, uint32_t oi, uintptr_t retaddr) {
  using Fn = void (*)(void*, uint32_t, uint16_t, uint32_t, uintptr_t);
  static const auto store = nxtmap::emu::required<Fn>("helper_le_stw_mmu_arm");
  nxtmap::emu::t_storeReturn = retaddr;
  store(env, addr, val, oi, retaddr);
  nxtmap::emu::t_storeReturn = 0;
}
void helper_le_stl_mmu_arm(void* env, uint32_t addr, uint32_t val, uint32_t oi, uintptr_t retaddr) {
  using Fn = void (*)(void*, uint32_t, uint32_t, uint32_t, uintptr_t);
  static const auto store = nxtmap::emu::required<Fn>("helper_le_stl_mmu_arm");
  nxtmap::emu::t_storeReturn = retaddr;
  store(env, addr, val, oi, retaddr);
  nxtmap::emu::t_storeReturn = 0;
}
}
