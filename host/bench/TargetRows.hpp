// TargetRows: a bench section's table of measures against their targets (PASS / MISS, or information), printed
// with its columns aligned and a count of the targets met.
#pragma once

#include <algorithm>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace nxtmap::bench {

inline const char* verdict(bool ok) { return ok ? "PASS" : "MISS"; }

// `whatColumn`: the second column's heading ("strategy", "map / algorithm"); `summary`: what the last line counts
// ("targets met"). A row's `result`: "PASS", "MISS" or "" (information, no target).
class TargetRows {
 public:
  TargetRows(std::string whatColumn, std::string summary)
      : head_{"measure", std::move(whatColumn), "measured", "target", "result"}, summary_(std::move(summary)) {}
  void add(const std::string& measure, const std::string& what, const std::string& measured, const std::string& target,
           const std::string& result) {
    rows_.push_back({measure, what, measured, target, result});
    if (result == "PASS") ++pass_;
    if (result == "PASS" || result == "MISS") ++targets_;
  }
  void rule() { rows_.push_back({}); }  // a line of dashes between groups of rows
  void print() const {
    std::vector<size_t> w(head_.size());
    for (size_t i = 0; i < head_.size(); ++i) w[i] = head_[i].size();
    for (const auto& r : rows_)
      for (size_t i = 0; i < r.size(); ++i) w[i] = std::max(w[i], r[i].size());
    size_t total = 0;
    for (size_t x : w) total += x + 2;
    const std::string dashes(total - 2, '-');
    printLine(head_, w);
    std::cout << dashes << '\n';
    for (const auto& r : rows_) {
      if (r.empty())
        std::cout << dashes << '\n';
      else
        printLine(r, w);
    }
    std::cout << dashes << '\n' << summary_ << ": " << pass_ << " of " << targets_ << '\n';
  }

 private:
  static void printLine(const std::vector<std::string>& r, const std::vector<size_t>& w) {
    std::string s;
    for (size_t i = 0; i < r.size(); ++i) s += r[i] + std::string(w[i] - r[i].size() + 2, ' ');
    while (!s.empty() && s.back() == ' ') s.pop_back();
    std::cout << s << '\n';
  }

  std::vector<std::string> head_;
  std::string summary_;
  std::vector<std::vector<std::string>> rows_;
  int pass_ = 0, targets_ = 0;
};

}  // namespace nxtmap::bench
