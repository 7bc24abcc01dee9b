#include "host/emu/Machine.hpp"

#include "host/emu/AlignedAccess.hpp"
#include "host/emu/DirectStores.hpp"
#include "host/emu/MachineHooks.hpp"
#include "host/emu/UnicornFastPath.hpp"
#include "host/log/Log.hpp"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace nxtmap::emu {

namespace {
constexpr uint8_t kPaint = 0xA5;
// The guard's bytes on pages shared with .bss and the stacks are checked this often (and when run() returns):
// after every slice cost 2 % of the host time.
constexpr uint64_t kPaintCheckCycles = cyclesFromMs(1);
void check(uc_err e, const char* what) {
  if (e != UC_ERR_OK) throw std::runtime_error(std::string("unicorn: ") + what + ": " + uc_strerror(e));
}

}  // namespace

Machine::Machine(const ElfImage& image, const MachineOptions& options)
    : image_(image),
      options_(options),
      pmc_([this] {
        idle_ = true;
        maxBusy_ = std::max(maxBusy_, clock_.now - busyStart_);
        clock_.poke();
      }),
      mc_([this] { applyRemap(); }, efc_) {  // remap immediate, as on the chip (safe inside the MMIO callback)
  // Debugging aid: NXTMAP_EMU_TRACE logs every block (area "emu", level debug, which it turns on).
  trace_ = std::getenv("NXTMAP_EMU_TRACE") != nullptr;
  if (trace_ && !log::enabled(log::Level::Debug)) log::setLevel(log::Level::Debug);
  if (std::getenv("NXTMAP_EMU_NOALIGN")) options_.checkAlignment = false;
  if (std::getenv("NXTMAP_EMU_SLOW_STORES")) setUnicornFastStores(false);
  if (std::getenv("NXTMAP_EMU_LOAD_HOOK")) setAlignedAccessAllowed(false);
  flashRestore_.reserve(64);
  if (!flash_ || !ram_) throw std::bad_alloc();
  std::memcpy(flash_, image.flash().data(), kFlashSize);
  std::memset(ram_, kPaint, kRamSize);  // stack painting for the high-water mark
  const bool ramImage = !image.hasFlashCode();
  if (ramImage) {  // RAM-run image (fwexec style): copy what the ELF loads into RAM
    for (const auto& [offset, size] : image.ramSegments())
      std::memcpy(ram_ + offset, image.ram().data() + offset, size);
  }

  check(uc_open(UC_ARCH_ARM, UC_MODE_ARM, &uc_), "open");
  // Must come before the first mapping, or Unicorn silently uses a Cortex-A15.
  check(uc_ctl_set_cpu_model(uc_, UC_CPU_ARM_TI925T), "cpu model TI925T");
  mapFlash(kFlashBase);
  mapFlash(0);  // the mirror until the remap
  // Alignment is checked by Unicorn itself where it can (AlignedAccess); otherwise a hook on every load and
  // store checks it, and the stack guard too. Any memory hook sends every load and store down Unicorn's slow
  // path, so without one the guard is made of pages (StackGuard).
  alignedAccess_ = options_.checkAlignment && alignedAccessAvailable();
  hookMemory_ = options_.checkAlignment && !alignedAccess_;
  // RAM stores stay in Unicorn's translated code (DirectStores) while no code runs from RAM.
  directRam_ = !hookMemory_ && directStoresAvailable() && !ramImage;
  const auto ebss = image.firstSymbol({"_ebss", "__bss_end__", "_end", "end"});
  const auto limit = image.firstSymbol({"__stack_limit__", "__stacks_start__", "__stack_limit", "_sstack"});
  guard_ = StackGuard(options.guardLow.value_or(ebss.value_or(0)), options.stackLimit.value_or(limit.value_or(0)));
  guard_.mapRam(uc_, ram_, !hookMemory_);
  check(uc_mmio_map(uc_, kMmioBase, kMmioSize, &Hooks::mmioRead, this, &Hooks::mmioWrite, this), "map MMIO");

  page_.assign(kMmioSize >> 4, 0);
  aic_.setClock(&clock_);
  attach(Aic::kBase, Aic::kSize, aic_);
  attach(Pmc::kBase, Pmc::kSize, pmc_);
  attach(ResetController::kBase, ResetController::kSize, rstc_);
  attach(Pit::kBase, 0x10, pit_);
  attach(Watchdog::kBase, 0x10, wdt_);
  attach(VoltageRegulator::kBase, 0x10, vreg_);
  attach(MemoryController::kBase, MemoryController::kSize, mc_);
  aic_.connect(Aic::kIdSys, [this] { return pit_.irqLine(); });
  aic_.connect(Aic::kIdSys, [this] { return efc_.irqLine(); });
  devices_.push_back(&efc_);

  uc_hook h{};
  check(uc_hook_add(uc_, &h, UC_HOOK_BLOCK, reinterpret_cast<void*>(&Hooks::block), this, 1, 0), "block hook");
  check(uc_hook_add(uc_, &h, UC_HOOK_MEM_UNMAPPED | UC_HOOK_MEM_PROT, reinterpret_cast<void*>(&Hooks::badMemory), this,
                    1, 0),
        "memory fault hook");
  check(uc_hook_add(uc_, &h, UC_HOOK_INTR, reinterpret_cast<void*>(&Hooks::interrupt), this, 1, 0), "intr hook");
  check(uc_hook_add(uc_, &h, UC_HOOK_INSN_INVALID, reinterpret_cast<void*>(&Hooks::invalidInsn), this, 1, 0),
        "invalid instruction hook");

  if (hookMemory_)
    check(uc_hook_add(uc_, &h, UC_HOOK_MEM_WRITE | UC_HOOK_MEM_READ, reinterpret_cast<void*>(&Hooks::memAccess), this,
                      1, 0),
          "memory hook");

  if (options.timedFunction) {
    std::optional<uint32_t> at = image.symbol(*options.timedFunction);
    if (!at) {
      char* end = nullptr;
      const unsigned long v = std::strtoul(options.timedFunction->c_str(), &end, 0);
      if (end && *end == '\0' && !options.timedFunction->empty()) at = static_cast<uint32_t>(v);
    }
    if (!at) throw std::runtime_error("timed function '" + *options.timedFunction + "' is not in the firmware");
    timedEntry_ = *at & ~1u;
    if (options.profileTimed) profile_ = std::make_unique<TimedProfile>();
    check(
        uc_hook_add(uc_, &h, UC_HOOK_CODE, reinterpret_cast<void*>(&Hooks::timedEntry), this, timedEntry_, timedEntry_),
        "timed function hook");
  }

  // Reset: ARM state, SVC mode, IRQ/FIQ masked, PC at the reset vector (or the entry of a RAM image).
  uint32_t cpsr = 0xD3;
  check(uc_reg_write(uc_, UC_ARM_REG_CPSR, &cpsr), "cpsr");
  uint32_t pc = ramImage ? image.entry() : 0;
  check(uc_reg_write(uc_, UC_ARM_REG_PC, &pc), "pc");
}

Machine::~Machine() {
  if (uc_) uc_close(uc_);
  std::free(flash_);
  std::free(ram_);
}

void Machine::attach(uint32_t base, uint32_t size, IoDevice& device) {
  if (base < kMmioBase || (base & 0xF) != 0 || size == 0 || uint64_t{base} + size > kMmioBase + kMmioSize)
    throw std::invalid_argument("attach: bad peripheral window");
  slots_.push_back(Slot{base, &device});
  const auto idx = static_cast<uint8_t>(slots_.size());
  for (uint64_t a = base; a < uint64_t{base} + size; a += 16) page_[(a - kMmioBase) >> 4] = idx;
  if (std::find(devices_.begin(), devices_.end(), &device) == devices_.end()) devices_.push_back(&device);
}

void Machine::setFault(FaultKind kind, uint32_t address, std::string what, std::optional<uint32_t> pc) {
  if (fault_) return;  // keep the first
  fault_.kind = kind;
  fault_.pc = pc.value_or(currentPc());
  fault_.address = address;
  fault_.what = std::move(what);
}

void Machine::reportModelFault(const std::string& what) {
  setFault(FaultKind::Model, 0, what);
  clock_.poke();  // the block hook stops at the next block, and run() ends
}

uint32_t Machine::currentPc() const {
  uint32_t pc = 0;
  uc_reg_read(uc_, UC_ARM_REG_PC, &pc);
  return pc ? pc : lastBlock_;
}

std::vector<uint8_t> Machine::flashContents() const {
  std::vector<uint8_t> bytes(flash_, flash_ + kFlashSize);
  for (const FlashWord& w : flashRestore_) std::memcpy(bytes.data() + w.offset, w.bytes, 4);
  return bytes;
}

void Machine::restoreFlash() {
  for (const FlashWord& w : flashRestore_) std::memcpy(flash_ + w.offset, w.bytes, 4);
  flashRestore_.clear();
}

void Machine::flashProgrammed(uint32_t offset, uint32_t bytes) {
  // Code translated from the old contents must not run again.
  uc_ctl_remove_cache(uc_, kFlashBase + offset, kFlashBase + offset + bytes);
  std::fill(modes_.begin() + (kFlashSize + offset) / 2, modes_.begin() + (kFlashSize + offset + bytes) / 2, 0);
  if (!remapped_) {
    uc_ctl_remove_cache(uc_, offset, offset + bytes);
    std::fill(modes_.begin() + offset / 2, modes_.begin() + (offset + bytes) / 2, 0);
  }
}

void Machine::applyRemap() {
  std::fill(modes_.begin(), modes_.begin() + kFlashSize / 2, 0);  // address 0 now shows other code
  remapped_ = !remapped_;                                         // RCB toggles (nxt-hardware.md 1.1)
  uc_mem_unmap(uc_, 0, remapped_ ? kFlashSize : kRamSize);
  if (remapped_)
    check(uc_mem_map_ptr(uc_, 0, kRamSize, UC_PROT_ALL, ram_), "remap RAM to 0");
  else
    mapFlash(0);
}

void Machine::mapFlash(uint64_t at) {
  check(uc_mem_map_ptr(uc_, at, kFlashSize, UC_PROT_READ | UC_PROT_EXEC, flash_), "map flash");
  // uc_mem_map_ptr records the permissions but leaves the pages writable for translated code without a
  // memory hook; protecting them again marks them read-only, so a store takes the path that checks them (the
  // EFC latch or a fault, see Hooks::badMemory) and leaves the flash as it was.
  check(uc_mem_protect(uc_, at, kFlashSize, UC_PROT_READ | UC_PROT_EXEC), "protect flash");
}

void Machine::checkGuardPaint() {
  paintCheckAt_ = clock_.now + kPaintCheckCycles;
  if (fault_) return;
  if (const std::optional<uint32_t> lost = guard_.paintLost(kPaint))
    stackOverflow(*lost, " (found painted over after the store: the PC is where the CPU stopped)");
}

void Machine::stackOverflow(uint32_t address, const char* how) {
  setFault(FaultKind::StackOverflow, address, "write below the stack limit " + hexWord(guard_.limit()) + how);
}

bool Machine::readByte(uint32_t a, uint8_t& v) const {
  if (a >= kRamBase && a < kRamBase + kRamSize) {
    v = ram_[a - kRamBase];
    return true;
  }
  if (a >= kFlashBase && a < kFlashBase + kFlashSize) {
    v = flash_[a - kFlashBase];
    return true;
  }
  if (remapped_ && a < kRamSize) {
    v = ram_[a];
    return true;
  }
  if (!remapped_ && a < kFlashSize) {
    v = flash_[a];
    return true;
  }
  return false;
}

bool Machine::writeByte(uint32_t a, uint8_t v) {
  if (a >= kRamBase && a < kRamBase + kRamSize) {
    ram_[a - kRamBase] = v;
    return true;
  }
  if (remapped_ && a < kRamSize) {
    ram_[a] = v;
    return true;
  }
  return false;
}

MachineStats Machine::stats() const {
  MachineStats s;
  s.cycles = clock_.now;
  s.executed = executed_;
  s.irqs = irqs_;
  s.lateIrqs = lateIrqs_;
  s.slices = slices_;
  s.idles = pmc_.idleRequests();
  s.maxBusy = std::max(maxBusy_, idle_ ? 0 : clock_.now - busyStart_);
  s.timedCalls = timedCalls_;
  s.maxTimed = maxTimed_;
  s.wallSeconds = wallSeconds_;
  s.cpuSeconds = cpuSeconds_;
  return s;
}

RamUse Machine::ramUse() const {
  RamUse r;
  const std::optional<uint32_t> end = image_.firstSymbol({"_ebss", "__bss_end__", "_end", "end"});
  r.measured = end.has_value();
  const uint32_t ebss = end.value_or(kRamBase);
  const uint32_t lo = std::clamp(ebss, kRamBase, kRamBase + kRamSize);
  r.staticBytes = lo - kRamBase;
  uint32_t lowest = kRamBase + kRamSize;
  for (uint32_t a = lo; a < kRamBase + kRamSize; ++a)
    if (ram_[a - kRamBase] != kPaint) {
      lowest = a;
      break;
    }
  r.stackBytes = kRamBase + kRamSize - lowest;
  return r;
}

}  // namespace nxtmap::emu

// LeakSanitizer (test builds): Unicorn 2.0.1 never frees the self-modifying-code bitmap it builds for a RAM page
// that holds code and is written (tb_invalidate_phys_page_fast -> build_page_bitmap), not even in uc_close.
// That is the library's leak, not ours; everything else stays checked. Without LSan this is never called.
extern "C" const char* __lsan_default_suppressions() { return "leak:tb_invalidate_phys_page_fast_arm\n"; }
