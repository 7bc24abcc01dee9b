#include "host/emu/UnicornFastPath.hpp"

#include <unicorn/unicorn.h>

#include <dlfcn.h>

#include <atomic>

namespace nxtmap::emu {
namespace {
bool defaultOn() {
  unsigned major = 0, minor = 0;
  uc_version(&major, &minor);
  return major == 2 && minor == 0;  // later releases carry the upstream fix themselves
}
std::atomic<bool> g_fast{defaultOn()};
}  // namespace

bool unicornFastStores() { return g_fast.load(std::memory_order_relaxed); }
void setUnicornFastStores(bool on) { g_fast.store(on && defaultOn(), std::memory_order_relaxed); }

}  // namespace nxtmap::emu

// Interposed over libunicorn's own definitions (exported from the executable, see host/CMakeLists.txt).
extern "C" {
void* page_collection_lock_arm(void* uc, unsigned long start, unsigned long end) {
  if (nxtmap::emu::unicornFastStores()) return nullptr;  // the result is only ever handed to _unlock
  using Fn = void* (*)(void*, unsigned long, unsigned long);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "page_collection_lock_arm"));
  return real ? real(uc, start, end) : nullptr;
}
void page_collection_unlock_arm(void* set) {
  if (set == nullptr) return;
  using Fn = void (*)(void*);
  static const auto real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "page_collection_unlock_arm"));
  if (real) real(set);
}
}
