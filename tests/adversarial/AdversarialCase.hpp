// AdversarialCase: one hostile but realistic input to the nxtmap console, as a row of a table. The suite runs
// each row's command as a user would and checks the house rule for bad input: one line on stderr starting
// with "nxtmap: ", exit code 2, nothing changed in the files around it, no crash, no hang, bounded memory.
// A row marked `works` is legitimate input that must succeed (exit 0) instead.
#pragma once
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace nxtmap::adversarial {

// Where a case runs: `dir` is a fresh directory (also the command's working directory's parent) holding the
// fixture files; `src` is the repository (read-only inputs such as worlds/).
struct CaseDirs {
  std::string dir, src;
  std::string path(const std::string& name) const { return dir + "/" + name; }
  // Writes `content` into dir/name (creating folders) and returns the path.
  std::string write(const std::string& name, const std::string& content) const;
  // Copies the repository file or folder `relative` to dir/name and returns the path.
  std::string copy(const std::string& relative, const std::string& name) const;
};

struct AdversarialCase {
  std::string name;               // a GoogleTest-safe identifier: [A-Za-z0-9_]
  std::vector<std::string> args;  // after `nxtmap`; "{dir}" and "{src}" are replaced by the paths
  std::function<void(const CaseDirs&)> setup = nullptr;         // fixture files, before the snapshot
  std::string stdinText;                                        // a console script, or "" for /dev/null
  double timeoutS = 30;                                         // the run is a hang past this (under ASan, with margin)
  bool works = false;                                           // legitimate input: exit 0 expected
  std::vector<std::string> creates;                             // works: files it must have created (relative to dir)
  std::function<std::string(const CaseDirs&)> check = nullptr;  // an extra check; "" when it holds
};

// GoogleTest prints a case as its command line.
void PrintTo(const AdversarialCase& c, std::ostream* os);

// The tables, one per area (LoaderCases.cpp, HouseCases.cpp, ...).
std::vector<AdversarialCase> loaderCases();
std::vector<AdversarialCase> houseCases();
std::vector<AdversarialCase> argumentCases();
std::vector<AdversarialCase> outputCases();
std::vector<AdversarialCase> linkCases();

// Peak memory any case may take, KiB (the sanitizer build's own overhead included).
constexpr long kMemoryBoundKiB = 1024L * 1024;  // 1 GiB

}  // namespace nxtmap::adversarial
