// EmuFault: why an emulated run stopped abnormally, with where (PC) and what address.
#pragma once

#include <cstdint>
#include <string>

namespace nxtmap::emu {

enum class FaultKind {
  None,
  Unaligned,      // word/halfword access at an address not a multiple of its size
  UnmodelledIo,   // a peripheral register no model handles
  BadMemory,      // read/write/fetch outside RAM/flash/peripherals, or a write to flash
  StackOverflow,  // a write below the stack area (into the gap above .bss or below RAM)
  Exception,      // undefined instruction, SWI, abort, or an instruction ARMv4T does not have
  Deadlock,       // the CPU clock is stopped and nothing can ever wake it
  Reset,          // the firmware asked the reset controller for a reset
  Model,          // a peripheral model saw something the hardware cannot do (e.g. TWI protocol error)
};

const char* faultKindName(FaultKind kind);

struct EmuFault {
  FaultKind kind = FaultKind::None;
  uint32_t pc = 0;       // the faulting instruction, or the start of its translation block
  uint32_t address = 0;  // the data address involved (0 if none)
  std::string what;      // one line: what happened
  explicit operator bool() const { return kind != FaultKind::None; }
  std::string describe() const;  // "unaligned access at pc=0x... address=0x...: ..."
};

}  // namespace nxtmap::emu
