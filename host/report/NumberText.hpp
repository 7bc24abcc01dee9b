// NumberText: whole-string numbers read from text (command-line values, table fields), nothing else accepted.
#pragma once
#include <string>

namespace nxtmap::report {

// `text` is a decimal int (optional sign, leading blanks skipped as strtol does, nothing after it, within int's
// range): true and `value` set; otherwise false and `value` untouched.
bool parseWholeInt(const std::string& text, int& value);
// `text` is a finite number as strtod reads it (nothing after it): true and `value` set; otherwise false and
// `value` untouched.
bool parseFiniteDouble(const std::string& text, double& value);

}  // namespace nxtmap::report
