// Where the benches find the worlds they run (Appendix A rooms, Moving AI maps, HouseExpo plans, rooms).
#pragma once

#include <filesystem>

namespace nxtmap::bench {

// The worlds/ directory: ./worlds when run from the source tree's root (it holds seed-appendix-a), else the
// source tree's own, the one this file was compiled in.
std::filesystem::path worldsRoot();

}  // namespace nxtmap::bench
