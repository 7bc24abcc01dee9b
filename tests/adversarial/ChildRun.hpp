// ChildRun: runs the nxtmap binary as a user would (its own process, arguments, a stdin script), with a
// deadline and a measure of its peak memory, for the adversarial suite.
#pragma once
#include <string>
#include <vector>

namespace nxtmap::adversarial {

struct ChildResult {
  bool timedOut = false;   // killed (SIGKILL) at the deadline
  bool signalled = false;  // ended by a signal (a crash), not by exit()
  int exitCode = -1;       // exit() status when !signalled && !timedOut
  int signal = 0;          // the signal when signalled
  long peakRssKiB = 0;     // the child's peak resident set (getrusage ru_maxrss), KiB
  double seconds = 0;      // wall time from start to end
  std::string out, err;    // what it wrote on stdout and stderr
};

// Runs `program args...` in `cwd` with `stdinText` on its standard input (empty: /dev/null), stdout and stderr
// captured through files under `scratch`, killed after `timeoutS` seconds (then timedOut).
ChildResult runChild(const std::string& program, const std::vector<std::string>& args, const std::string& cwd,
                     const std::string& stdinText, const std::string& scratch, double timeoutS);

}  // namespace nxtmap::adversarial
