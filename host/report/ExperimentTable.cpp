#include "host/report/ExperimentTable.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace nxtmap::report {
namespace {
std::string pad(const std::string& s, size_t width, bool right) {
  if (s.size() >= width) return s;
  return right ? std::string(width - s.size(), ' ') + s : s + std::string(width - s.size(), ' ');
}

std::string ratio(double ours, double published) {
  if (published == 0) return "-";
  return formatNumber(ours / published, 2) + "x";
}
}  // namespace

void ExperimentRow::summarize() {
  mean = RunResult{};
  if (perSeed.empty()) return;
  const double n = static_cast<double>(perSeed.size());
  minDetectedPct = perSeed.front().detectedPct;
  maxWrongCells = perSeed.front().wrongCells;
  mean.complete = true;
  int squared = 0;
  for (const RunResult& r : perSeed) {
    if (r.squared) {
      mean.squaredDeg += r.squaredDeg;
      ++squared;
    }
    mean.actualFree += r.actualFree / n;
    mean.foundFree += r.foundFree / n;
    mean.actualOccupied += r.actualOccupied / n;
    mean.foundOccupied += r.foundOccupied / n;
    mean.unknown += r.unknown / n;
    mean.unknownObservable += r.unknownObservable / n;
    mean.wrongCells += r.wrongCells / n;
    mean.detectedPct += r.detectedPct / n;
    mean.performancePct += r.performancePct / n;
    mean.timeUnits += r.timeUnits / n;
    mean.sensorReads += r.sensorReads / n;
    mean.unsafeFree += r.unsafeFree / n;
    mean.phantomOccupied += r.phantomOccupied / n;
    mean.lost += r.lost / n;
    mean.detectedPctAligned += r.detectedPctAligned / n;
    mean.wrongCellsAligned += r.wrongCellsAligned / n;
    mean.headingOffPct += r.headingOffPct / n;
    mean.positionOffPct += r.positionOffPct / n;
    mean.roomCells = r.roomCells;
    mean.complete = mean.complete && r.complete;
    minDetectedPct = std::min(minDetectedPct, r.detectedPct);
    maxWrongCells = std::max(maxWrongCells, r.wrongCells);
  }
  mean.squared = squared > 0;
  if (mean.squared) mean.squaredDeg /= squared;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

std::string formatNumber(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

namespace {
template <typename F>
double medianOf(const std::vector<ExperimentRow>& rows, F field) {
  std::vector<double> v;
  v.reserve(rows.size());
  for (const ExperimentRow& r : rows) v.push_back(field(r));
  return median(v);
}
}  // namespace

double ExperimentTable::medianTimeUnits() const {
  return medianOf(rows, [](const ExperimentRow& r) { return r.mean.timeUnits; });
}
double ExperimentTable::medianSensorReads() const {
  return medianOf(rows, [](const ExperimentRow& r) { return r.mean.sensorReads; });
}
double ExperimentTable::medianUnknown() const {
  return medianOf(rows, [](const ExperimentRow& r) { return r.mean.unknown; });
}
double ExperimentTable::publishedMedianTimeUnits() const {
  return medianOf(rows, [](const ExperimentRow& r) { return r.scenario.seedTimeUnits; });
}
double ExperimentTable::publishedMedianSensorReads() const {
  return medianOf(rows, [](const ExperimentRow& r) { return static_cast<double>(r.scenario.seedSensorCount); });
}
double ExperimentTable::publishedMedianUnknowns() const {
  return medianOf(rows, [](const ExperimentRow& r) { return static_cast<double>(r.scenario.seedUnknowns); });
}

namespace {
// The values of kSafetyColumns, kPoseColumns and kStartColumns, each after a comma.
std::string safetyFields(const RunResult& m) {
  return "," + formatNumber(m.unsafeFree) + "," + formatNumber(m.phantomOccupied) + "," + formatNumber(m.lost) + "," +
         formatNumber(m.detectedPctAligned) + "," + formatNumber(m.wrongCellsAligned) + "," +
         formatNumber(m.headingOffPct) + "," + formatNumber(m.positionOffPct) + "," +
         (m.squared ? formatNumber(m.squaredDeg) : "");
}
}  // namespace

const char* ExperimentTable::csvHeader() {
  static const std::string header =
      std::string(
          "id,actual_free,found_free,actual_occupied,found_occupied,unknown,wrong_cells,detected_pct,"
          "time_units,sensor_reads,seed_time_units,seed_sensor_count,seed_detected_pct,") +
      kSafetyColumns + "," + kPoseColumns + "," + kStartColumns;
  return header.c_str();
}

void ExperimentTable::writeCsv(std::ostream& out) const {
  out << csvHeader() << '\n';
  for (const ExperimentRow& r : rows) {
    const RunResult& m = r.mean;
    const Scenario& s = r.scenario;
    out << s.id << ',' << formatNumber(m.actualFree) << ',' << formatNumber(m.foundFree) << ','
        << formatNumber(m.actualOccupied) << ',' << formatNumber(m.foundOccupied) << ',' << formatNumber(m.unknown)
        << ',' << formatNumber(m.wrongCells) << ',' << formatNumber(m.detectedPct) << ',' << formatNumber(m.timeUnits)
        << ',' << formatNumber(m.sensorReads) << ',' << formatNumber(s.seedTimeUnits) << ',' << s.seedSensorCount << ','
        << formatNumber(s.seedDetectedPct) << safetyFields(m) << '\n';
  }
}

void ExperimentTable::writeSeedCsv(std::ostream& out, bool header) const {
  if (header) {
    out << "id,strategy,noise,seed,actual_free,found_free,actual_occupied,found_occupied,unknown,"
           "unknown_observable,wrong_cells,detected_pct,performance_pct,time_units,sensor_reads,complete,"
        << kSafetyColumns << ',' << kPoseColumns << ',' << kStartColumns << '\n';
  }
  for (const ExperimentRow& r : rows) {
    for (size_t i = 0; i < r.perSeed.size(); ++i) {
      const RunResult& m = r.perSeed[i];
      out << r.scenario.id << ',' << strategy << ',' << noise << ',' << (i + 1) << ',' << formatNumber(m.actualFree)
          << ',' << formatNumber(m.foundFree) << ',' << formatNumber(m.actualOccupied) << ','
          << formatNumber(m.foundOccupied) << ',' << formatNumber(m.unknown) << ',' << formatNumber(m.unknownObservable)
          << ',' << formatNumber(m.wrongCells) << ',' << formatNumber(m.detectedPct) << ','
          << formatNumber(m.performancePct) << ',' << formatNumber(m.timeUnits) << ',' << formatNumber(m.sensorReads)
          << ',' << (m.complete ? 1 : 0) << safetyFields(m) << '\n';
    }
  }
}

void ExperimentTable::writeMarkdown(std::ostream& out) const {
  out << "### Strategy `" << strategy << "`, noise `" << noise << "`";
  if (seeds > 1) out << ", mean of " << seeds << " seeds";
  out << "\n\n";
  out << "| run | occupied | time units | published | sensor reads | published | unknown | published "
         "| detected % | published | wrong cells |\n";
  out << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for (const ExperimentRow& r : rows) {
    const RunResult& m = r.mean;
    const Scenario& s = r.scenario;
    out << "| " << s.id << " | " << s.occupiedCells << " | " << formatNumber(m.timeUnits) << " | "
        << formatNumber(s.seedTimeUnits) << " | " << formatNumber(m.sensorReads) << " | " << s.seedSensorCount << " | "
        << formatNumber(m.unknown) << " | " << s.seedUnknowns << " | " << formatNumber(m.detectedPct, 1) << " | "
        << formatNumber(s.seedDetectedPct, 1) << " | " << formatNumber(m.wrongCells) << " |\n";
  }
  out << "| **median** | | **" << formatNumber(medianTimeUnits()) << "** | **"
      << formatNumber(publishedMedianTimeUnits()) << "** | **" << formatNumber(medianSensorReads()) << "** | **"
      << formatNumber(publishedMedianSensorReads()) << "** | **" << formatNumber(medianUnknown()) << "** | **"
      << formatNumber(publishedMedianUnknowns()) << "** | | | |\n\n";
  out << "Ours / published medians: time " << ratio(medianTimeUnits(), publishedMedianTimeUnits()) << ", sensor reads "
      << ratio(medianSensorReads(), publishedMedianSensorReads()) << ".\n";
}

void ExperimentTable::writeConsole(std::ostream& out) const {
  out << "strategy " << strategy << ", noise " << noise;
  if (seeds > 1) out << ", mean of " << seeds << " seeds";
  out << "   (ours | published)\n";
  const std::vector<std::pair<std::string, size_t>> cols = {{"run", 16},    {"occ", 4}, {"time", 7},    {"pub", 6},
                                                            {"sensors", 8}, {"pub", 6}, {"unknown", 8}, {"pub", 4},
                                                            {"detect%", 8}, {"pub", 4}, {"wrong", 6}};
  auto emit = [&](const std::vector<std::string>& cells) {
    std::string line;
    for (size_t i = 0; i < cols.size(); ++i) {
      if (i > 0) line += (i == 2 || i == 4 || i == 6 || i == 8 || i == 10) ? " | " : " ";
      line += pad(cells[i], cols[i].second, i != 0);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    out << line << '\n';
  };
  std::vector<std::string> head;
  for (const auto& c : cols) head.push_back(c.first);
  emit(head);
  for (const ExperimentRow& r : rows) {
    const RunResult& m = r.mean;
    const Scenario& s = r.scenario;
    emit({s.id, std::to_string(s.occupiedCells), formatNumber(m.timeUnits, 1), formatNumber(s.seedTimeUnits, 1),
          formatNumber(m.sensorReads, 1), std::to_string(s.seedSensorCount), formatNumber(m.unknown, 1),
          std::to_string(s.seedUnknowns), formatNumber(m.detectedPct, 1), formatNumber(s.seedDetectedPct, 1),
          formatNumber(m.wrongCells, 1)});
  }
  emit({"median", "", formatNumber(medianTimeUnits(), 1), formatNumber(publishedMedianTimeUnits(), 1),
        formatNumber(medianSensorReads(), 1), formatNumber(publishedMedianSensorReads(), 1),
        formatNumber(medianUnknown(), 1), formatNumber(publishedMedianUnknowns(), 1), "", "", ""});
  out << "ours/published medians: time " << ratio(medianTimeUnits(), publishedMedianTimeUnits()) << ", sensor reads "
      << ratio(medianSensorReads(), publishedMedianSensorReads()) << '\n';
  const Squaring s = squaring();
  if (s.squared > 0) {
    out << "squared to the walls in " << s.squared << " of " << s.runs << " runs: left "
        << formatNumber(std::fabs(s.meanDeg), 2) << " deg " << (s.meanDeg < 0 ? "anticlockwise" : "clockwise")
        << " of them on average, " << formatNumber(s.rmsDeg, 2) << " deg rms\n";
  }
}

ExperimentTable::Squaring ExperimentTable::squaring() const {
  Squaring s;
  double sum = 0, squares = 0;
  for (const ExperimentRow& row : rows) {
    for (const RunResult& r : row.perSeed) {
      ++s.runs;
      if (!r.squared) continue;
      ++s.squared;
      sum += r.squaredDeg;
      squares += r.squaredDeg * r.squaredDeg;
    }
  }
  if (s.squared > 0) {
    s.meanDeg = sum / s.squared;
    s.rmsDeg = std::sqrt(squares / s.squared);
  }
  return s;
}

}  // namespace nxtmap::report
