#include "host/house/HouseTrace.hpp"

#include <iomanip>

#include "host/mapping/RunTrace.hpp"

namespace nxtmap::house {

HouseTrace::HouseTrace(std::ostream& out) : out_(out) {
  out_ << "step,order,action,value,sensor,reading_cm,reading,"
          "true_col,true_row,true_heading_deg,"
          "believed_col,believed_row,believed_heading,est_x_mm,est_y_mm,est_theta_mrad,lost\n";
}

void HouseTrace::record(const HouseTraceRow& r) {
  ++steps_;
  out_ << steps_ << ',' << r.order << ',' << mapping::actionName(r.done.kind) << ',' << r.done.value << ',';
  if (r.done.kind == DriveAction::Kind::Read && r.answer.kind == DriveEvent::Kind::Range)
    out_ << "FRBL"[static_cast<int>(r.answer.sensor) & 3] << ',' << r.answer.reading.cm << ','
         << mapping::statusName(r.answer.reading.status);
  else
    out_ << ",,";
  out_ << std::fixed << std::setprecision(2) << ',' << r.trueCol << ',' << r.trueRow << ',' << std::setprecision(1)
       << r.trueHeadingDeg << ',';
  if (r.believed)
    out_ << r.believedCol << ',' << r.believedRow << ',' << r.believedHeading << ',' << r.estXMm << ',' << r.estYMm
         << ',' << r.estThetaMrad << ',' << (r.lost ? 1 : 0) << '\n';
  else
    out_ << ",,,,,,\n";
  if (r.believed && r.lost) {
    ++lostSteps_;
    if (firstLost_ == 0) firstLost_ = steps_;
  }
}

}  // namespace nxtmap::house
