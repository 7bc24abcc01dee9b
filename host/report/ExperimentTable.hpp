// ExperimentTable: the results of running the Appendix-A scenario list (Scenario), side by side with the
// published figures; writers for CSV, Markdown and the console.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "host/report/Scenario.hpp"

namespace nxtmap::report {

// The columns both CSVs end with, after their older columns (readers of those keep working).
constexpr const char* kSafetyColumns = "unsafe_free,phantom_occupied,lost,detected_pct_aligned,wrong_cells_aligned";
// The localisation (mapping::PoseErrorShare): % of the explorer's actions with the heading over 40 mrad off, and
// with the centre over a quarter of a cell off the believed one.
constexpr const char* kPoseColumns = "heading_off_pct,position_off_pct";
// The start's sweep (mapping::MappingRun::squaredTurnedDeg): how far the robot was left off the walls' axis,
// degrees, + clockwise; empty for a run whose sweep found no wall or that had none (a scenario's row: the mean
// over its seeds that found them).
constexpr const char* kStartColumns = "squared_deg";

// The thesis's medians over the 18 runs (Chapter 5).
constexpr double kPublishedMedianTimeUnits = 350.5;
constexpr double kPublishedMedianSensorReads = 1143.5;

// The figures of one mapping run.
struct RunResult {
  double actualFree = 0, foundFree = 0, actualOccupied = 0, foundOccupied = 0;
  double unknown = 0, unknownObservable = 0, wrongCells = 0;
  double detectedPct = 0;     // detected / observable occupied cells
  double performancePct = 0;  // the thesis's found occupied / actual occupied
  double timeUnits = 0, sensorReads = 0;
  double roomCells = 0;  // world width * height
  bool complete = true;  // the explorer finished normally
  // Safety (mapping::MapScore): a mean over seeds is a mean count; `lost` is 0/1, its mean the share lost.
  double unsafeFree = 0, phantomOccupied = 0, lost = 0;
  double detectedPctAligned = 0, wrongCellsAligned = 0;  // after the best rigid alignment to the world
  double headingOffPct = 0, positionOffPct = 0;          // mapping::PoseErrorShare
  bool squared = false;                                  // the start's sweep found the walls (kStartColumns)
  double squaredDeg = 0;                                 // then: the heading left off their axis, deg, + clockwise
};

// One scenario's results: the mean over the seeds plus the spread.
struct ExperimentRow {
  Scenario scenario;
  std::vector<RunResult> perSeed;  // seeds 1..N in order
  RunResult mean;
  double minDetectedPct = 0;
  double maxWrongCells = 0;
  // Fills mean/min/max from perSeed.
  void summarize();
};

double median(std::vector<double> values);
// Shortest decimal form with at most `decimals` places: 294, 294.5, 97.87.
std::string formatNumber(double value, int decimals = 2);

// The results of one strategy over the scenario table.
struct ExperimentTable {
  std::string strategy;
  std::string noise = "none";
  int seeds = 1;
  std::vector<ExperimentRow> rows;

  double medianTimeUnits() const;
  double medianSensorReads() const;
  double medianUnknown() const;
  double publishedMedianTimeUnits() const;
  double publishedMedianSensorReads() const;
  double publishedMedianUnknowns() const;

  // CSV header: the published comparison columns, then the safety columns (kSafetyColumns), the localisation's
  // (kPoseColumns) and the start's (kStartColumns).
  static const char* csvHeader();
  // One row per scenario (means over the seeds).
  void writeCsv(std::ostream& out) const;
  // Per-seed detail: id,strategy,seed,<figures>.
  void writeSeedCsv(std::ostream& out, bool header = true) const;
  // A Markdown table: ours beside the published figures, a medians row at the bottom.
  void writeMarkdown(std::ostream& out) const;
  // An aligned plain-text table for the console, and how square the runs that swept started (when any did).
  void writeConsole(std::ostream& out) const;
  // Over every run that squared to the walls: how many, of how many runs, the mean and rms of squaredDeg.
  struct Squaring {
    int squared = 0, runs = 0;
    double meanDeg = 0, rmsDeg = 0;
  };
  Squaring squaring() const;
};

}  // namespace nxtmap::report
