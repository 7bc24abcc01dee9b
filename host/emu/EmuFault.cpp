#include "host/emu/EmuFault.hpp"

#include <cstdio>

namespace nxtmap::emu {

const char* faultKindName(FaultKind kind) {
  switch (kind) {
    case FaultKind::None: return "no fault";
    case FaultKind::Unaligned: return "unaligned access";
    case FaultKind::UnmodelledIo: return "unmodelled peripheral register";
    case FaultKind::BadMemory: return "bad memory access";
    case FaultKind::StackOverflow: return "stack overflow";
    case FaultKind::Exception: return "unexpected exception";
    case FaultKind::Deadlock: return "deadlock";
    case FaultKind::Reset: return "reset requested";
    case FaultKind::Model: return "peripheral protocol error";
  }
  return "?";
}

std::string EmuFault::describe() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, " at pc=0x%08x address=0x%08x", static_cast<unsigned>(pc),
                static_cast<unsigned>(address));
  return std::string(faultKindName(kind)) + buf + (what.empty() ? "" : ": " + what);
}

}  // namespace nxtmap::emu
