#include "host/report/Scenario.hpp"

#include "host/report/NumberText.hpp"

#include <filesystem>
#include <fstream>

namespace nxtmap::report {
namespace {
constexpr int kColumns = 11;
const char* const kColumnNames[kColumns] = {"id",
                                            "map",
                                            "start_col",
                                            "start_row",
                                            "seed_x_m",
                                            "seed_z_m",
                                            "occupied_cells",
                                            "seed_unknowns",
                                            "seed_time_units",
                                            "seed_sensor_count",
                                            "seed_detected_pct"};

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> out;
  std::string::size_type from = 0;
  while (true) {
    const auto tab = line.find('\t', from);
    out.push_back(line.substr(from, tab == std::string::npos ? std::string::npos : tab - from));
    if (tab == std::string::npos) break;
    from = tab + 1;
  }
  return out;
}
}  // namespace

ScenarioLoad loadScenarios(const std::string& tsvPath) {
  ScenarioLoad load;
  std::ifstream in(tsvPath);
  if (!in) {
    load.error = tsvPath + ": cannot open the scenario table";
    return load;
  }
  const std::filesystem::path dir = std::filesystem::path(tsvPath).parent_path();
  std::string line;
  int lineNo = 0;
  auto fail = [&](const std::string& what) {
    load.scenarios.clear();
    load.error = tsvPath + " line " + std::to_string(lineNo) + ": " + what;
    return load;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos || line[0] == '#') continue;
    const std::vector<std::string> f = splitTabs(line);
    if (f.size() != kColumns) {
      return fail("expected " + std::to_string(kColumns) + " tab-separated columns, found " + std::to_string(f.size()));
    }
    Scenario s;
    s.line = lineNo;
    s.id = f[0];
    s.map = f[1];
    if (s.id.empty()) return fail("empty id");
    if (s.map.empty()) return fail("empty map");
    bool ok = parseWholeInt(f[2], s.startCol) && parseWholeInt(f[3], s.startRow);
    if (!ok) return fail("start_col/start_row must be integers, found '" + f[2] + "', '" + f[3] + "'");
    const struct {
      int index;
      double* target;
    } doubles[] = {{4, &s.seedXM}, {5, &s.seedZM}, {8, &s.seedTimeUnits}, {10, &s.seedDetectedPct}};
    for (const auto& d : doubles) {
      if (!parseFiniteDouble(f[static_cast<size_t>(d.index)], *d.target))
        return fail(std::string(kColumnNames[d.index]) + " must be a number, found '" +
                    f[static_cast<size_t>(d.index)] + "'");
    }
    const struct {
      int index;
      int* target;
    } ints[] = {{6, &s.occupiedCells}, {7, &s.seedUnknowns}, {9, &s.seedSensorCount}};
    for (const auto& d : ints) {
      if (!parseWholeInt(f[static_cast<size_t>(d.index)], *d.target))
        return fail(std::string(kColumnNames[d.index]) + " must be an integer, found '" +
                    f[static_cast<size_t>(d.index)] + "'");
    }
    for (const Scenario& other : load.scenarios) {
      if (other.id == s.id)
        return fail("duplicate id '" + s.id + "' (first on line " + std::to_string(other.line) + ")");
    }
    const std::filesystem::path mp(s.map);
    s.mapPath = (mp.is_absolute() || dir.empty()) ? mp.string() : (dir / mp).string();
    load.scenarios.push_back(std::move(s));
  }
  if (load.scenarios.empty()) {
    load.error = tsvPath + ": no scenarios in the table";
  }
  return load;
}

}  // namespace nxtmap::report
