// Helpers for the trace tests (`sim --trace`, `sim-house --trace`): a CSV row's fields, what the run's last line
// says of the belief leaving the robot's cell, and the bad trace files every command refuses before its run.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "CliTestSupport.hpp"

namespace nxtmap::cli::test {

// The comma-separated fields of a row, empty ones (a trailing one too) kept.
inline std::vector<std::string> csvFields(const std::string& row) {
  std::vector<std::string> out;
  std::istringstream in(row);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  if (!row.empty() && row.back() == ',') out.push_back("");
  return out;
}

// What a run's trace line says when the belief first left the robot's cell after action `firstLost` (0: never).
inline std::string lostSummary(long firstLost, long lostRows) {
  std::ostringstream s;
  if (firstLost == 0)
    s << "the believed cell was the robot's after every action";
  else
    s << "first left the robot's after action " << firstLost << " (" << lostRows << " actions lost in all)";
  return s.str();
}

// `command` (a run, without --trace) with a trace that is not a .csv, in a missing folder, or a folder: exit 2,
// one line on stderr, no run (`runMarker` not printed) and nothing written.
inline void expectBadTracesRefused(const std::string& command, const std::string& runMarker) {
  TempDir tmp("badtrace");
  for (const std::string& bad : {tmp.path("run.txt"), tmp.path("no/such/folder/run.csv"), tmp.path("") + "/"}) {
    SCOPED_TRACE(bad);
    const RunOutput r = runCli(command + " --trace " + bad);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
    EXPECT_EQ(r.out.find(runMarker), std::string::npos) << "no run: " << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(tmp.path("run.txt")));
  EXPECT_FALSE(std::filesystem::exists(tmp.path("no")));
}

}  // namespace nxtmap::cli::test
