#pragma once
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::mapping {

// The exploration strategies behind the one explorer interface.
enum class Strategy { Propagation, Frontier };

std::optional<Strategy> strategyByName(const std::string& name);
std::string strategyName(Strategy s);
std::vector<std::string> strategyNames();

}  // namespace nxtmap::mapping
