// The few C++ runtime hooks a freestanding image needs, without libstdc++.
#include "common/check/Check.hpp"

extern "C" void __cxa_pure_virtual() { nxtmap::checkFailed(__FILE__, __LINE__, "pure virtual call"); }
