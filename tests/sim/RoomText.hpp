// The 4 x 3 m room as world-file text, shared by the WorldFile tests (WorldFileTest, WorldFileBadTest).
#pragma once

#include <string>

namespace nxtmap::sim::test {

inline const std::string kRoom = "nxtmap_world: 1\noutline:\n  polygon: [[0, 0], [4, 0], [4, 3], [0, 3]]\n";

// The 4 x 3 m room with `more` appended (obstacles:, start:, ...).
inline std::string room(const std::string& more) { return kRoom + more; }

}  // namespace nxtmap::sim::test
