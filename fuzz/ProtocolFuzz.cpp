// libFuzzer entry for the protocol decoder (`make fuzz`). A failed property aborts with its name.
#include <cstdio>
#include <cstdlib>

#include "fuzz/ProtocolFuzzBody.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (const char* bad = nxtmap::fuzz::runProtocolInput(data, size)) {
    std::fprintf(stderr, "property failed: %s\n", bad);
    std::abort();
  }
  return 0;
}
