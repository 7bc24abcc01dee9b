#pragma once
#include <optional>
#include <string>
#include <vector>

#include "common/explore/ExplorerStack.hpp"

namespace nxtmap::mapping {

// The exploration strategies behind the one explorer interface: the common core's own.
using Strategy = nxtmap::Strategy;

// The mapping strategies a user may ask for: propagation, frontier (GoTo maps nothing: never offered).
std::optional<Strategy> strategyByName(const std::string& name);
std::string strategyName(Strategy s);  // "propagation", "frontier", "goto"
std::vector<std::string> strategyNames();

}  // namespace nxtmap::mapping
