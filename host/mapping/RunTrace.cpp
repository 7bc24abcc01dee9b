#include "host/mapping/RunTrace.hpp"

#include <algorithm>
#include <cmath>

#include "host/mapping/MappingRun.hpp"

namespace nxtmap::mapping {
namespace {

constexpr double kPi = 3.14159265358979323846;
}  // namespace

const char* actionName(DriveAction::Kind k) {
  switch (k) {
    case DriveAction::Kind::Read: return "read";
    case DriveAction::Kind::Rotate: return "rotate";
    case DriveAction::Kind::Drive: return "drive";
    case DriveAction::Kind::Done: return "done";
    case DriveAction::Kind::Think: return "think";
  }
  return "?";
}

const char* statusName(RangeStatus s) {
  switch (s) {
    case RangeStatus::Good: return "good";
    case RangeStatus::NoEcho: return "no-echo";
    case RangeStatus::TooNear: return "too-near";
    case RangeStatus::TooFar: return "too-far";
    case RangeStatus::Inconsistent: return "inconsistent";
  }
  return "?";
}

TracePose tracePose(const MappingRun& run) {
  const sim::SimRobot& robot = run.robot();
  const sim::GridFrame& grid = robot.frame();
  const FrameTransform& frame = run.frame();
  const double cellMm = grid.cellCm * 10.0;
  TracePose t;

  // The truth: the centre on the world grid, then along the explorer's axes (whole-cell unit vectors).
  const sim::Vec2 g = grid.toGrid(sim::Vec2(robot.xCm(), robot.yCm()));
  const double dCol = g.x() - run.config().startCol, dRow = g.y() - run.config().startRow;
  int ox = 0, oy = 0, exCol = 0, exRow = 0, eyCol = 0, eyRow = 0;
  frame.toWorld(Cell{0, 0}, ox, oy);
  frame.toWorld(Cell{1, 0}, exCol, exRow);
  frame.toWorld(Cell{0, 1}, eyCol, eyRow);
  t.trueXMm = (dCol * (exCol - ox) + dRow * (exRow - oy)) * cellMm;
  t.trueYMm = (dCol * (eyCol - ox) + dRow * (eyRow - oy)) * cellMm;
  const double northDeg = sim::headingToDeg(frame.toWorld(Dir::North));
  const double trueDeg = std::remainder(robot.headingDeg() - grid.headingDeg - northDeg, 360.0);

  // The belief: the explorer's cell and heading, the tracker's offset.
  const Pose p = run.explorer().pose();
  t.cellX = p.cell.x;
  t.cellY = p.cell.y;
  t.headingQuarters = static_cast<int>(p.heading);
  const PoseTracker& tracker = run.pilot().tracker();
  t.estXMm = tracker.xMm();
  t.estYMm = tracker.yMm();
  t.estThetaMrad = tracker.thetaMrad();
  const auto sd = [](int64_t variance) { return std::sqrt(static_cast<double>(std::max<int64_t>(variance, 0))); };
  t.sdXMm = sd(tracker.varianceAlong(Dir::East));
  t.sdYMm = sd(tracker.varianceAlong(Dir::North));
  t.sdThetaMrad = sd(tracker.thetaVariance());
  t.mapping = run.pilot().explorerStarted();

  t.trueThetaMrad = std::remainder(trueDeg - 90.0 * t.headingQuarters, 360.0) * kPi / 0.18;
  t.errXMm = t.trueXMm - (t.cellX * cellMm + t.estXMm);
  t.errYMm = t.trueYMm - (t.cellY * cellMm + t.estYMm);
  t.errThetaMrad = t.trueThetaMrad - t.estThetaMrad;
  int col = 0, row = 0, believedCol = 0, believedRow = 0;
  grid.cellOf(sim::Vec2(robot.xCm(), robot.yCm()), col, row);
  run.believedCell(believedCol, believedRow);
  t.lost = col != believedCol || row != believedRow;
  return t;
}

RunTrace::RunTrace(std::ostream& out) : out_(out) {
  out_ << "step,action,value,sensor,reading_cm,reading,"
          "true_x_mm,true_y_mm,true_theta_mrad,"
          "cell_x,cell_y,heading,est_x_mm,est_y_mm,est_theta_mrad,"
          "err_x_mm,err_y_mm,err_theta_mrad,lost,sd_x_mm,sd_y_mm,sd_theta_mrad\n";
}

void RunTrace::record(const MappingRun& run, uint64_t step, const DriveAction& done) {
  const TracePose t = tracePose(run);
  const auto whole = [](double v) { return std::lround(v); };
  out_ << step << ',' << actionName(done.kind) << ',' << done.value << ',';
  const DriveEvent& e = run.lastEvent();
  if (done.kind == DriveAction::Kind::Read && e.kind == DriveEvent::Kind::Range)
    out_ << "FRBL"[static_cast<int>(e.sensor) & 3] << ',' << e.reading.cm << ',' << statusName(e.reading.status);
  else
    out_ << ",,";
  out_ << ',' << whole(t.trueXMm) << ',' << whole(t.trueYMm) << ',' << whole(t.trueThetaMrad) << ',' << t.cellX << ','
       << t.cellY << ',' << "NESW"[t.headingQuarters & 3] << ',' << t.estXMm << ',' << t.estYMm << ',' << t.estThetaMrad
       << ',' << whole(t.errXMm) << ',' << whole(t.errYMm) << ',' << whole(t.errThetaMrad) << ',' << (t.lost ? 1 : 0)
       << ',' << whole(t.sdXMm) << ',' << whole(t.sdYMm) << ',' << whole(t.sdThetaMrad) << '\n';
  if (t.lost) {
    ++lostSteps_;
    if (firstLost_ == 0) firstLost_ = step;
  }
  if (t.mapping) {
    ++mappingSteps_;
    const auto outside = [](double err, double sd) { return std::fabs(err) > 3.0 * sd + 1.0; };
    if (outside(t.errXMm, t.sdXMm) || outside(t.errYMm, t.sdYMm) || outside(t.errThetaMrad, t.sdThetaMrad))
      ++outsideSteps_;
  }
  worstMm_ = std::max(worstMm_, std::hypot(t.errXMm, t.errYMm));
  worstMrad_ = std::max(worstMrad_, std::fabs(t.errThetaMrad));
}

}  // namespace nxtmap::mapping
