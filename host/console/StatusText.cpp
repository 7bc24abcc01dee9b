#include "host/console/StatusText.hpp"

#include <cstdio>
#include <sstream>

#include "host/report/ExperimentTable.hpp"

namespace nxtmap::console {
namespace {

const char* const kModes[] = {"idle", "exploring", "following a path", "done exploring", "fault"};

const char* modeText(const protocol::StatusMsg& st) { return kModes[static_cast<int>(st.mode)]; }

// The brick's and the PC's counters.
void countersText(std::ostream& o, const link::Session& s) {
  if (s.brickCounters()) {
    const auto& k = *s.brickCounters();
    o << "brick: " << k.explorer.sensorRequests << " readings, " << k.explorer.cellsMoved << " cells moved, "
      << k.explorer.turnEighths << " turn eighths, " << k.link.commandsRun << " commands run, " << k.link.duplicates
      << " duplicates ignored, " << k.link.retransmits << " map retransmissions\n";
    // Learnt from the walls as it goes (PoseTracker): what its wheels do beyond what they are told.
    char drift[48];
    std::snprintf(drift, sizeof drift, "%+.2f deg/m", k.wheelDrift10UradPerM * 1e-5 * 57.29578);
    o << "wheels: drift " << drift << ", turns " << turnErrorText(k) << " (learnt)\n";
  }
  const auto& pc = s.counters();
  o << "pc: " << pc.bytesIn << " bytes in, " << pc.deltasApplied << " map deltas, " << pc.commandsAcknowledged
    << " commands acknowledged, " << pc.commandRetries << " resent, " << s.decoderCounters().skipped
    << " noise bytes skipped, " << pc.connects << " connects\n";
}

}  // namespace

std::string statusText(const link::Session& s, const std::string& linkText, const GoalDriver& goals) {
  std::ostringstream o;
  o << "link: " << linkText << ", " << (s.connected() ? "connected" : "not connected") << "\n";
  if (s.status()) {
    const protocol::StatusMsg& st = *s.status();
    o << "robot: " << modeText(st) << " at (" << st.pose.cell.x << "," << st.pose.cell.y
      << "), off the cell's centre by " << report::formatNumber(st.offsetXMm / 10.0, 1) << ","
      << report::formatNumber(st.offsetYMm / 10.0, 1) << " cm (x, y), battery " << st.batteryMillivolts << " mV\n";
  }
  o << "map: " << s.map().known() << " known cells, epoch " << s.map().epoch() << "\n";
  countersText(o, s);
  if (!goals.outcome().empty() || goals.active())
    o << "goal: " << (goals.active() ? "on the way" : goals.outcome()) << "\n";
  return o.str();
}

std::string statusLineText(const std::string& linkState, const link::Session& s, const GoalDriver& goals) {
  std::ostringstream o;
  o << linkState;
  if (s.status()) o << " | robot " << modeText(*s.status());
  o << " | map " << s.map().known() << " cells";
  if (goals.active()) o << " | goal " << goals.routeCells() << "-cell route";
  return o.str();
}

std::string turnErrorText(const protocol::CountersMsg& k) {
  char text[48];
  std::snprintf(text, sizeof text, "%+.2f %%", k.wheelTurn10Ppm * 1e-3);
  return text;
}

std::string calibrationText(const std::string& before, const std::string& after) {
  if (after == before)
    return "not calibrated: the turns' error is still " + after +
           " (no straight wall in reach of the sweep where the robot stands, or its turns stalled)\n";
  return "calibrated: turns " + after + " off (before: " + before + "); the brick corrects its turns by it and keeps it\n";
}

std::string batteryText(const std::optional<uint16_t>& millivolts, const std::optional<uint16_t>& legoMillivolts) {
  std::ostringstream o;
  o << "battery: " << (millivolts ? std::to_string(*millivolts) : std::string("?"))
    << " mV (LEGO GET_BATTERY_LEVEL: " << (legoMillivolts ? std::to_string(*legoMillivolts) : std::string("no answer"))
    << ")\n";
  return o.str();
}

}  // namespace nxtmap::console
