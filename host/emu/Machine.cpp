#include "host/emu/Machine.hpp"

#include "host/emu/AccessBytes.hpp"
#include "host/emu/AlignedAccess.hpp"
#include "host/emu/DirectStores.hpp"
#include "host/emu/MachineHooks.hpp"
#include "host/emu/StoreSite.hpp"
#include "host/emu/UnicornFastPath.hpp"
#include "host/log/Log.hpp"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

namespace nxtmap::emu {

namespace {
constexpr uint8_t kPaint = 0xA5;
// The guard's bytes on pages shared with .bss and the stacks are checked this often (and when run() returns):
// after every slice cost 2 % of the host time.
constexpr uint64_t kPaintCheckCycles = cyclesFromMs(1);
constexpr uint64_t kMaskedPoll = 256;  // re-check a masked pending IRQ every this many cycles

double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

double wallNow() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

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

void Machine::advanceModels() {
  for (IoDevice* d : devices_) d->advanceTo(clock_.now);
  aic_.sample();
}

uint64_t Machine::nextEvent() const {
  uint64_t t = kNever;
  for (const IoDevice* d : devices_) t = std::min(t, d->nextEventAt());
  return t;
}

void Machine::takeIrq() {
  uint32_t cpsr = 0, pc = 0;
  uc_reg_read(uc_, UC_ARM_REG_CPSR, &cpsr);
  uc_reg_read(uc_, UC_ARM_REG_PC, &pc);
  enterIrq(cpsr, pc);
}

void Machine::irqAfterStore(uint32_t address, unsigned bytes, uint32_t value) {
  if (fault_ || idle_) return;
  uint32_t cpsr = 0;
  uc_reg_read(uc_, UC_ARM_REG_CPSR, &cpsr);
  if (cpsr & kCpsrI) return;
  aic_.sample();
  if (!aic_.irqAsserted()) return;
  static const int ids[15] = {UC_ARM_REG_R0,  UC_ARM_REG_R1,  UC_ARM_REG_R2,  UC_ARM_REG_R3, UC_ARM_REG_R4,
                              UC_ARM_REG_R5,  UC_ARM_REG_R6,  UC_ARM_REG_R7,  UC_ARM_REG_R8, UC_ARM_REG_R9,
                              UC_ARM_REG_R10, UC_ARM_REG_R11, UC_ARM_REG_R12, UC_ARM_REG_SP, UC_ARM_REG_LR};
  std::array<uint32_t, 16> regs{};
  for (int i = 0; i < 15; ++i) uc_reg_read(uc_, ids[i], &regs[static_cast<size_t>(i)]);
  const bool thumb = (cpsr & kCpsrT) != 0;
  // Without a memory hook the store is known exactly (DirectStores): decode it alone. Otherwise the block is
  // searched, the hook's count of its writes telling stores that look alike apart.
  uint32_t from = lastBlock_, span = lastBlockBytes_;
  unsigned ordinal = blockWrites_;
  uint32_t pc = 0;
  if (!hookMemory_ && directStoresAvailable() && restoreStorePc(cpu_) &&
      uc_reg_read(uc_, UC_ARM_REG_PC, &pc) == UC_ERR_OK && pc - lastBlock_ < lastBlockBytes_) {
    from = pc;
    span = thumb ? 2 : 4;
    ordinal = 1;
  }
  const auto site = findStoreSite(*this, from, span, thumb, regs, address, bytes, value, ordinal);
  if (!site) {
    ++lateIrqs_;  // taken at the block's end, as before
    log::debug("emu",
               "IRQ raised by a store to %08x in block %08x (+%u, write %u): store not found, taken at the block's end",
               static_cast<unsigned>(address), static_cast<unsigned>(lastBlock_), lastBlockBytes_, blockWrites_);
    return;
  }
  log::debug("emu", "IRQ raised by the store at %08x to %08x: taken before %08x", static_cast<unsigned>(site->pc),
             static_cast<unsigned>(address), static_cast<unsigned>(site->next));
  // The store was the last instruction to run: Unicorn leaves the block after it (a PC write stops the block
  // and resumes at the new PC), so the base writeback and the rest of the block are not run or counted.
  if (site->base >= 0) uc_reg_write(uc_, ids[site->base], &site->baseValue);
  const uint64_t skipped = (lastBlock_ + lastBlockBytes_ - site->next) / (thumb ? 2 : 4);
  clock_.now -= skipped;
  executed_ -= skipped;
  const uint32_t next = site->next | (thumb ? 1u : 0u);
  uc_reg_write(uc_, UC_ARM_REG_PC, &next);  // resumes at `next`, where the block hook stops (clock poked)
  stepBeforeIrq_ = true;
}

std::string Machine::unalignedWhat(bool store) const {
  uint32_t cpsr = 0;
  uc_reg_read(uc_, UC_ARM_REG_CPSR, &cpsr);
  const bool thumb = (cpsr & kCpsrT) != 0;
  const uint32_t pc = currentPc();
  uint32_t insn = 0;
  for (uint32_t i = 0; i < (thumb ? 2u : 4u); ++i) {
    uint8_t b = 0;
    if (readByte(pc + i, b)) insn |= uint32_t{b} << (8 * i);
  }
  const char* what = store ? "write" : "read";
  const unsigned bytes = store ? storeBytes(insn, thumb) : loadBytes(insn, thumb);
  return bytes ? what + (" of " + std::to_string(bytes) + " bytes") : std::string(what);
}

uint32_t Machine::instructionBytes(uint32_t pc, bool thumb) const {
  if (!thumb) return 4;
  uint8_t hi = 0;
  return readByte(pc + 1, hi) && (hi >> 3) == 0x1E ? 4 : 2;  // a BL prefix translates with its suffix
}

void Machine::enterIrq(uint32_t cpsr, uint32_t pc) {
  const uint32_t irqCpsr = (cpsr & ~0x3Fu) | kCpsrI | 0x12;  // IRQ mode, ARM state, IRQs masked
  uc_reg_write(uc_, UC_ARM_REG_CPSR, &irqCpsr);              // banks SP/LR first
  uc_reg_write(uc_, UC_ARM_REG_SPSR, &cpsr);
  const uint32_t lr = pc + 4;
  uc_reg_write(uc_, UC_ARM_REG_LR, &lr);
  const uint32_t vec = 0x18;
  uc_reg_write(uc_, UC_ARM_REG_PC, &vec);
  ++irqs_;
}

void Machine::paceToWall() {
  if (!options_.realtime) return;
  const double target = wallOrigin_ + secondsFromCycles(clock_.now);
  const double ahead = target - wallNow();
  if (ahead > 0.0005) std::this_thread::sleep_for(std::chrono::duration<double>(ahead));
}

bool Machine::run(uint64_t until, const std::function<bool()>& stop) {
  const double wallStart = wallNow();
  const double cpuStart = cpuNow();
  if (wallOrigin_ < 0.0) wallOrigin_ = wallStart - secondsFromCycles(clock_.now);
  while (!fault_) {
    advanceModels();
    if (fault_) break;  // a model reported one
    if (!efc_.misuse().empty()) {
      setFault(FaultKind::BadMemory, kFlashBase + efc_.misuseOffset(), efc_.misuse());
      break;
    }
    if (wdt_.expired()) {
      setFault(FaultKind::Reset, 0, "watchdog timeout (WDT not disabled or restarted)");
      break;
    }
    if (rstc_.resetRequested()) {
      setFault(FaultKind::Reset, 0, "processor reset requested via RSTC_RCR");
      break;
    }
    if (stop && stop()) break;
    if (clock_.now >= until) break;

    if (idle_) {
      if (aic_.wakeAsserted()) {
        idle_ = false;
        busyStart_ = clock_.now;
      } else {
        uint64_t t = nextEvent();
        if (options_.realtime) t = std::min(t, clock_.now + cyclesFromMs(2));
        if (t == kNever) {
          if (externalWait_ && externalWait_()) continue;
          setFault(FaultKind::Deadlock, 0, "processor clock stopped and no interrupt source can wake it");
          break;
        }
        clock_.now = std::max(clock_.now, std::min(t, until));
        paceToWall();
        continue;
      }
    }

    uint32_t cpsr = 0;
    uc_reg_read(uc_, UC_ARM_REG_CPSR, &cpsr);
    const bool step = stepBeforeIrq_;  // one instruction after the store that raised the IRQ runs first
    stepBeforeIrq_ = false;
    const bool irq = aic_.irqAsserted();
    if (irq && !step && !(cpsr & kCpsrI)) {
      takeIrq();
      cpsr = (cpsr & ~0x3Fu) | kCpsrI | 0x12;
    }
    uint64_t stopAt = std::min(nextEvent(), until);
    if (irq && (cpsr & kCpsrI)) stopAt = std::min(stopAt, clock_.now + kMaskedPoll);
    if (options_.realtime) stopAt = std::min(stopAt, clock_.now + cyclesFromMs(1));
    clock_.stopAt = step ? clock_.now + 1 : std::max(stopAt, clock_.now + 1);
    uint32_t pc = 0;
    uc_reg_read(uc_, UC_ARM_REG_PC, &pc);
    const uint64_t begin = pc | ((cpsr & kCpsrT) ? 1u : 0u);
    stoppedAt_ = 0;
    ++slices_;
    // The step translates afresh, so that Unicorn stops at `end`: a block cached at pc would run on past it.
    if (step) uc_ctl_remove_cache(uc_, pc, pc + 1);
    const uint64_t end = step ? pc + instructionBytes(pc, (cpsr & kCpsrT) != 0) : 0xFFFFFFF0ull;
    setAlignedAccess(alignedAccess_);
    setDirectRamStores(directRam_ ? kRamBase : 0, directRam_ ? kRamBase + kRamSize : 0);
    setCpuSlot(&cpu_);
    const uc_err e = uc_emu_start(uc_, begin, end, 0, 0);
    setCpuSlot(nullptr);
    restoreFlash();
    if (clock_.now >= paintCheckAt_) checkGuardPaint();
    if (stoppedAt_ != 0 && !fault_) {
      // Stopped by the block hook before that block ran. Unicorn 2.0.1 sometimes leaves PC past the
      // block's first instructions (seen on a chained Thumb cmp/beq block); the block did not execute,
      // so resume exactly at it.
      uint32_t now = 0;
      uc_reg_read(uc_, UC_ARM_REG_CPSR, &now);
      const uint32_t pcT = stoppedAt_ | ((now & kCpsrT) ? 1u : 0u);  // writing PC sets the T bit from bit 0
      uc_reg_write(uc_, UC_ARM_REG_PC, &pcT);
    }
    if (e != UC_ERR_OK && !fault_) setFault(FaultKind::BadMemory, 0, std::string("unicorn: ") + uc_strerror(e));
    paceToWall();
  }
  checkGuardPaint();
  wallSeconds_ += wallNow() - wallStart;
  cpuSeconds_ += cpuNow() - cpuStart;
  return !fault_;
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
