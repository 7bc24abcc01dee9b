// Machine's run loop: the models advanced to the clock, interrupts taken when they are due (and right after the
// store that raised one), and the CPU run in slices up to the next event, paced to the wall clock on request.
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
#include <chrono>
#include <ctime>
#include <thread>

namespace nxtmap::emu {

namespace {
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

}  // namespace

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

}  // namespace nxtmap::emu
