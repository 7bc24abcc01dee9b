#include "host/mapping/PoseErrorShare.hpp"

#include <cmath>

#include "host/mapping/MappingRun.hpp"
#include "host/mapping/RunTrace.hpp"

namespace nxtmap::mapping {

void PoseErrorShare::add(const MappingRun& run) {
  if (!run.hasPilot() || !run.pilot().explorerStarted()) return;
  const TracePose t = tracePose(run);
  const double quarterCellMm = run.robot().frame().cellCm * 10.0 / 4.0;
  ++actions_;
  if (std::fabs(t.errThetaMrad) > kHeadingMrad) ++headingOff_;
  if (std::hypot(t.errXMm, t.errYMm) > quarterCellMm) ++positionOff_;
}

}  // namespace nxtmap::mapping
