// Surface: how a piece of the world's geometry answers the ultrasonic sensor.
#pragma once

#include <optional>
#include <string>

namespace nxtmap::sim {

// Hard: a smooth wall, furniture side or glass: a strong echo square on, specular (no echo or a phantom)
//       at a grazing incidence. Soft: a curtain, a sofa's cushions: absorbs, the echo is weak and short-ranged.
// Thin: a table or chair leg, a pole: a weak target, seen late or not at all (nxt-sonar-and-odometry.md).
enum class Surface { Hard, Soft, Thin };

// "hard", "soft", "thin" -> Surface; anything else -> nullopt.
inline std::optional<Surface> surfaceFromName(const std::string& name) {
  if (name == "hard") return Surface::Hard;
  if (name == "soft") return Surface::Soft;
  if (name == "thin") return Surface::Thin;
  return std::nullopt;
}

inline const char* surfaceName(Surface s) {
  switch (s) {
    case Surface::Hard: return "hard";
    case Surface::Soft: return "soft";
    case Surface::Thin: return "thin";
  }
  return "hard";
}

}  // namespace nxtmap::sim
