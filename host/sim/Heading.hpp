// Heading: the four nominal compass directions of the simulated robot.
// N = towards row 0 (y decreasing), E = towards larger col (x increasing); clockwise order N, E, S, W.
#pragma once

#include <optional>

namespace nxtmap::sim {

enum class Heading { N, E, S, W };

// 'N'/'E'/'S'/'W' (either case) -> Heading; anything else -> nullopt.
inline std::optional<Heading> headingFromChar(char c) {
  switch (c) {
    case 'N':
    case 'n': return Heading::N;
    case 'E':
    case 'e': return Heading::E;
    case 'S':
    case 's': return Heading::S;
    case 'W':
    case 'w': return Heading::W;
    default: return std::nullopt;
  }
}

// Heading -> degrees clockwise from N: 0, 90, 180, 270.
inline double headingToDeg(Heading h) { return 90.0 * static_cast<int>(h); }

}  // namespace nxtmap::sim
