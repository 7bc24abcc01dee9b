// Machine: the AT91SAM7S256 core on Unicorn. ARMv4T CPU (TI925T model), 256 KiB flash at 0x100000 and
// 64 KiB RAM at 0x200000 with the address-0 remap, one MMIO dispatcher for 0xFFFA0000..0xFFFFFFFF with a
// model per peripheral, the instruction count as the clock, IRQs injected at block boundaries or, when a
// store raised one, after the instruction that follows the store (StoreSite), and
// fast-forward while the firmware has stopped the processor clock. The system controller models
// (AIC, PIT, PMC, WDT, RSTC, VREG, MC) belong to the machine; board peripherals are attached.
// Faults (unaligned access, unmodelled register, bad memory, stack overflow, exceptions) stop the run.
#pragma once

#include "host/emu/Aic.hpp"
#include "host/emu/Clock.hpp"
#include "host/emu/ElfImage.hpp"
#include "host/emu/EmuFault.hpp"
#include "host/emu/FlashController.hpp"
#include "host/emu/IoDevice.hpp"
#include "host/emu/MemoryController.hpp"
#include "host/emu/Pit.hpp"
#include "host/emu/Pmc.hpp"
#include "host/emu/ResetController.hpp"
#include "host/emu/StackGuard.hpp"
#include "host/emu/TimedProfile.hpp"
#include "host/emu/Watchdog.hpp"

#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

struct uc_struct;

namespace nxtmap::emu {

struct MachineOptions {
  bool checkAlignment = true;  // trap unaligned loads/stores (Unicorn checks them, see AlignedAccess, or a hook)
  bool realtime = false;       // pace emulated time to the wall clock
  // Lowest address the stacks may use: writes in [guardLow, stackLimit) are a stack overflow.
  // Taken from the ELF (_ebss/__bss_end__ .. __stack_limit__/__stacks_start__) when not set.
  std::optional<uint32_t> guardLow, stackLimit;
  // Time one function from entry to return (e.g. the sensor update), by symbol name or address.
  std::optional<std::string> timedFunction;
  // Keep where the instructions of the timed function's costliest call went (timedProfile()).
  bool profileTimed = false;
};

struct RamUse {
  uint32_t staticBytes = 0;  // RAM base .. end of .bss (vectors, .data, .bss)
  uint32_t stackBytes = 0;   // deepest stack use found by painting (RAM top down)
  bool measured = false;     // the image names the end of .bss (else both figures mean nothing)
  uint32_t total() const { return staticBytes + stackBytes; }
};

struct MachineStats {
  uint64_t cycles = 0;       // emulated cycles (= instructions executed + idle cycles skipped)
  uint64_t executed = 0;     // instructions executed
  uint64_t irqs = 0;         // IRQs entered
  uint64_t lateIrqs = 0;     // IRQs a store made pending, taken at its block's end (the store not found)
  uint64_t slices = 0;       // times the CPU was (re)started: IRQs, events, pokes
  uint64_t idles = 0;        // times the processor clock was stopped
  uint64_t maxBusy = 0;      // longest stretch of instructions between two idles
  uint64_t timedCalls = 0;   // calls of the timed function
  uint64_t maxTimed = 0;     // most instructions in one call of it (including interrupts taken)
  double wallSeconds = 0.0;  // host time spent in run()
  double cpuSeconds = 0.0;   // host CPU time of the running thread spent in run() (load-independent)
};

class Machine : public GuestMemory {
 public:
  Machine(const ElfImage& image, const MachineOptions& options);
  ~Machine() override;
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  Clock& clock() { return clock_; }
  Aic& aic() { return aic_; }
  Pmc& pmc() { return pmc_; }
  const FlashController& flash() const { return efc_; }
  // The flash's 256 KiB as the chip holds them now (what a power cycle would keep).
  std::vector<uint8_t> flashContents() const;
  const ElfImage& image() const { return image_; }

  // Attaches a board peripheral at [base, base+size) (a multiple of 16 bytes, inside the MMIO window).
  void attach(uint32_t base, uint32_t size, IoDevice& device);
  // A model with its own time (e.g. the wheels) that has no registers.
  void addTimeSource(IoDevice& device) { devices_.push_back(&device); }

  // Runs until `until` cycles, a fault, or stop() returning true (checked at every event boundary).
  // Returns false on a fault (see fault()).
  bool run(uint64_t untilCycles, const std::function<bool()>& stop = {});
  // Called when the CPU is idle and no model will ever produce an event: return true if something
  // external (e.g. the PC link) may have changed state; false ends the run with a deadlock fault.
  void setExternalWait(std::function<bool()> wait) { externalWait_ = std::move(wait); }

  const EmuFault& fault() const { return fault_; }
  // A peripheral model saw something the hardware cannot do (e.g. the LCD an unknown command): the run
  // stops with a Model fault at the next block boundary (the first fault is kept).
  void reportModelFault(const std::string& what);
  MachineStats stats() const;
  // The costliest timed call's profile (MachineOptions::profileTimed), else nullptr.
  const TimedProfile* timedProfile() const { return profile_.get(); }
  RamUse ramUse() const;
  bool idle() const { return idle_; }

  bool readByte(uint32_t address, uint8_t& value) const override;
  bool writeByte(uint32_t address, uint8_t value) override;

  // Used by the Unicorn callbacks.
  struct Hooks;

 private:
  void setFault(FaultKind kind, uint32_t address, std::string what, std::optional<uint32_t> pc = {});
  uint32_t currentPc() const;
  void applyRemap();
  void mapFlash(uint64_t at);
  void advanceModels();
  uint64_t nextEvent() const;
  void takeIrq();
  // A store of `value` (`bytes`) at MMIO `address` may have made an IRQ deliverable: if so (CPSR.I clear),
  // the block stops after the store, the next instruction runs alone and then the IRQ is taken (one
  // instruction of latency, as the ARM7's nIRQ synchroniser gives), instead of at the block's end.
  void irqAfterStore(uint32_t address, unsigned bytes, uint32_t value);
  uint32_t instructionBytes(uint32_t pc, bool thumb) const;
  std::string unalignedWhat(bool store) const;  // "read of N bytes" / "write of N bytes" for the access at PC
  void stackOverflow(uint32_t address, const char* how = "");  // a store into the stack guard
  void checkGuardPaint();                                      // the guard's painted bytes (StackGuard::paintLost)
  void enterIrq(uint32_t cpsr, uint32_t pc);                   // IRQ mode, LR = pc + 4, PC = 0x18
  void paceToWall();
  void restoreFlash();
  void flashProgrammed(uint32_t offset, uint32_t bytes);

  const ElfImage& image_;
  MachineOptions options_;
  uc_struct* uc_ = nullptr;
  uint8_t* flash_ = static_cast<uint8_t*>(std::aligned_alloc(4096, kFlashSize));
  uint8_t* ram_ = static_cast<uint8_t*>(std::aligned_alloc(4096, kRamSize));
  Clock clock_;
  FlashController efc_{clock_, flash_, [this](uint32_t offset, uint32_t bytes) { flashProgrammed(offset, bytes); }};
  // A CPU store into flash fills the EFC latch; Unicorn also writes it into the flash buffer, so the words it
  // overwrote are put back at the next block boundary (flash offset, the 4 bytes before the store).
  struct FlashWord {
    uint32_t offset;
    uint8_t bytes[4];
  };
  std::vector<FlashWord> flashRestore_;
  Aic aic_;
  Pit pit_{clock_};
  Pmc pmc_;
  Watchdog wdt_{clock_};
  ResetController rstc_;
  VoltageRegulator vreg_;
  MemoryController mc_;
  std::vector<IoDevice*> devices_;  // all models, for time
  std::vector<uint8_t> page_;       // MMIO 16-byte slot -> 1 + index into slots_, 0 = none
  struct Slot {
    uint32_t base;
    IoDevice* device;
  };
  std::vector<Slot> slots_;
  bool remapped_ = false;
  bool idle_ = false;
  uint64_t executed_ = 0;
  uint64_t busyStart_ = 0;
  uint64_t maxBusy_ = 0;
  uint64_t irqs_ = 0;
  uint64_t slices_ = 0;
  uint32_t lastBlock_ = 0;
  uint32_t lastBlockBytes_ = 0;
  uint32_t blockWrites_ = 0;  // memory writes made in the current block (0 = unknown: no memory hook)
  uint64_t lateIrqs_ = 0;
  bool stepBeforeIrq_ = false;  // run one instruction before taking the IRQ a store raised
  bool alignedAccess_ = false;  // Unicorn checks alignment (AlignedAccess)
  bool hookMemory_ = false;     // a hook on every load and store (alignment, guard, blockWrites_); else none
  bool directRam_ = false;      // RAM stores stay in the translated code (DirectStores): no code ran from RAM
  void* cpu_ = nullptr;         // QEMU's CPUState of uc_ (DirectStores), once the CPU has run
  // Per halfword of code (address 0 window, flash, RAM): 0 unknown, 1 ARM, 2 Thumb. Code at an address keeps
  // its state; self-modifying code that switches state at an address is not supported.
  std::vector<uint8_t> modes_ = std::vector<uint8_t>((2 * kFlashSize + kRamSize) / 2, 0);
  int modeSlot(uint32_t a) const {  // index into modes_, -1 outside
    if (a < kFlashSize) return static_cast<int>(a >> 1);
    if (a - kFlashBase < kFlashSize) return static_cast<int>((kFlashSize + (a - kFlashBase)) >> 1);
    if (a - kRamBase < kRamSize) return static_cast<int>((2 * kFlashSize + (a - kRamBase)) >> 1);
    return -1;
  }
  bool inFlash(uint32_t a) const {  // flash, or its mirror at 0 before the remap
    return (a >= kFlashBase && a - kFlashBase < kFlashSize) || (!remapped_ && a < kFlashSize);
  }
  uint32_t stoppedAt_ = 0;  // block at which the block hook stopped the CPU (0 = none)
  StackGuard guard_{0, 0};
  uint64_t paintCheckAt_ = 0;  // clock at which the guard's paint is checked next
  uint32_t timedEntry_ = 0;
  uint32_t timedReturn_ = 0;  // 0 = not inside a timed call
  uint64_t timedStart_ = 0;
  uint64_t blockStart_ = 0;  // clock at the start of the current block
  uint64_t timedCalls_ = 0, maxTimed_ = 0;
  std::unique_ptr<TimedProfile> profile_;  // options_.profileTimed with a timed function
  // Inside a timed call with a profile kept: every block is counted.
  bool profiling() const { return timedReturn_ != 0 && profile_ != nullptr; }
  EmuFault fault_;
  std::function<bool()> externalWait_;
  bool trace_ = false;
  double wallSeconds_ = 0.0;
  double cpuSeconds_ = 0.0;
  double wallOrigin_ = -1.0;  // realtime pacing: wall second at cycle 0
};

}  // namespace nxtmap::emu
