// The few C++ runtime hooks a freestanding image needs, without libstdc++.
#include <cstdlib>

#include "common/check/Check.hpp"

extern "C" void __cxa_pure_virtual() { nxtmap::checkFailed(__FILE_NAME__, __LINE__, "pure virtual call"); }

// libstdc++'s throw helpers end in abort() without exceptions (std::variant's bad access, emitted by
// any use of std::variant even when never called). newlib's abort raises a signal, whose handler
// table is malloc'ed: this one is a failed check instead, and keeps the allocator out of the link.
extern "C" void abort() { nxtmap::checkFailed(__FILE_NAME__, __LINE__, "abort"); }
