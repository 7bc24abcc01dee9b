// ProgressLine: how far a long piece of work has come, "[LABEL] k of N: WHAT", on a stream (stderr).
// On a terminal the line is rewritten in place at every step and erased at the end. Anywhere else (a
// pipe, a CI log) it is written as whole lines: at the start, each time a tenth more of the way is done
// and at the end, so that a log of 1,800 runs holds 11 lines of progress, not 1,800 or one line of
// 1,800 carriage returns.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

namespace nxtmap::cli {

class ProgressLine {
 public:
  // total: the steps to come (>= 0; 0 prints the start and end lines only).
  ProgressLine(std::ostream& out, bool terminal, std::string label, size_t total);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  // `add` more steps done; `what` names the last (a run's id), may be empty.
  void tick(size_t add = 1, const std::string& what = "");

 private:
  void write(const std::string& what);

  std::ostream& out_;
  bool terminal_;
  std::string label_;
  size_t total_ = 0, done_ = 0;
  size_t tenths_ = 0;  // tenths of the way written as lines so far (not on a terminal)
};

}  // namespace nxtmap::cli
