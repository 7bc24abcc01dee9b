// The text `nxtmap sim` prints after a run: where and how it ran, what the start's sweep and calibration found,
// what the wheels learnt, the counters and the score against the world; and the line about a written trace.
#pragma once
#include <string>

#include "host/mapping/MappingRun.hpp"
#include "host/mapping/PoseErrorShare.hpp"
#include "host/mapping/RunTrace.hpp"
#include "host/sim/RobotDescription.hpp"

namespace nxtmap::cli {

// The run's report, from its "run" line to its last: `robot` the one it ran, `heading` as asked (N, E, S, W),
// `wheelsFile` the wheels file read at the start ("" for none), `pose` what its actions showed of the belief
// against the truth.
std::string simRunReport(const mapping::MappingRun& run, const sim::RobotDescription& robot,
                         const mapping::PoseErrorShare& pose, const std::string& heading,
                         const std::string& wheelsFile);

// Where the trace went and what it shows of the belief leaving the robot's cell.
std::string traceLine(const mapping::RunTrace& t, const std::string& file);

}  // namespace nxtmap::cli
