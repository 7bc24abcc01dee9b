#include "host/sim/NoiseProfile.hpp"

namespace nxtmap::sim {

std::optional<NoiseProfile> noiseProfileByName(const std::string& name) {
  const std::string canonical = name == "none" ? "ideal" : name;
  for (const std::string& known : noiseProfileNames()) {
    if (known != canonical) continue;
    return NoiseProfile{canonical, sonarPreset(canonical), wheelPreset(canonical)};
  }
  return std::nullopt;
}

std::vector<std::string> noiseProfileNames() { return {"ideal", "typical", "nxt", "nxt-uncalibrated", "harsh"}; }

std::string describeNoiseProfiles() {
  std::string out;
  for (const std::string& name : noiseProfileNames()) {
    const NoiseProfile p = *noiseProfileByName(name);
    out += name + ":\n  sonar:\n";
    for (const std::string& line : describeSonar(p.sonar)) out += "    " + line + "\n";
    out += "  wheels:\n";
    for (const std::string& line : describeWheels(p.wheels)) out += "    " + line + "\n";
  }
  return out;
}

}  // namespace nxtmap::sim
