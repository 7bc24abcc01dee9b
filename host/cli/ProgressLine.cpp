#include "host/cli/ProgressLine.hpp"

#include <utility>

namespace nxtmap::cli {

ProgressLine::ProgressLine(std::ostream& out, bool terminal, std::string label, size_t total)
    : out_(out), terminal_(terminal), label_(std::move(label)), total_(total) {
  write("");
}

ProgressLine::~ProgressLine() {
  if (terminal_) {
    out_ << "\r\x1b[K" << std::flush;
  } else if (done_ < total_) {  // stopped short (an error): say where
    out_ << "[" << label_ << "] stopped at " << done_ << " of " << total_ << "\n" << std::flush;
  }
}

void ProgressLine::tick(size_t add, const std::string& what) {
  done_ += add;
  if (terminal_) {
    write(what);
    return;
  }
  const size_t tenths = total_ == 0 ? 10 : (done_ >= total_ ? 10 : done_ * 10 / total_);
  if (tenths > tenths_) {
    tenths_ = tenths;
    write(what);
  }
}

void ProgressLine::write(const std::string& what) {
  if (terminal_) out_ << "\r\x1b[K";
  out_ << "[" << label_ << "] " << done_ << " of " << total_;
  if (!what.empty()) out_ << ": " << what;
  out_ << (terminal_ ? "" : "\n") << std::flush;
}

}  // namespace nxtmap::cli
