#include "host/mapping/Strategy.hpp"

namespace nxtmap::mapping {

std::optional<Strategy> strategyByName(const std::string& name) {
  if (name == "propagation") return Strategy::Propagation;
  if (name == "frontier") return Strategy::Frontier;
  return std::nullopt;
}

std::string strategyName(Strategy s) {
  switch (s) {
    case Strategy::Propagation: return "propagation";
    case Strategy::Frontier: return "frontier";
    case Strategy::GoTo: return "goto";
  }
  return "?";
}

std::vector<std::string> strategyNames() { return {"propagation", "frontier"}; }

}  // namespace nxtmap::mapping
