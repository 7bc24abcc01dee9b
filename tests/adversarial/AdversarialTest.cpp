// The adversarial suite: every row of the tables, run through the nxtmap binary (see AdversarialCase.hpp).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>

#include "tests/adversarial/AdversarialCase.hpp"
#include "tests/adversarial/ChildRun.hpp"
#include "tests/adversarial/TreeSnapshot.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::adversarial {
namespace fs = std::filesystem;

std::string CaseDirs::write(const std::string& name, const std::string& content) const {
  const fs::path p = fs::path(dir) / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

std::string CaseDirs::copy(const std::string& relative, const std::string& name) const {
  const fs::path to = fs::path(dir) / name;
  fs::create_directories(to.parent_path());
  fs::copy(fs::path(src) / relative, to, fs::copy_options::recursive);
  return to.string();
}

// What GoogleTest prints for a case: its command line (not the object's bytes).
void PrintTo(const AdversarialCase& c, std::ostream* os) {
  *os << "nxtmap";
  for (const std::string& a : c.args) *os << ' ' << a;
}

namespace {

// The binary under test: the build's own, or NXTMAP_CLI_UNDER_TEST (a copy held still while the tree rebuilds).
std::string cliUnderTest() {
  const char* other = std::getenv("NXTMAP_CLI_UNDER_TEST");
  return other != nullptr && *other != '\0' ? other : NXTMAP_CLI_PATH;
}

std::vector<AdversarialCase> allCases() {
  std::vector<AdversarialCase> all;
  for (auto table : {loaderCases, houseCases, argumentCases, outputCases, linkCases}) {
    for (AdversarialCase& c : table()) all.push_back(std::move(c));
  }
  return all;
}

std::string substitute(std::string arg, const CaseDirs& d) {
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"{dir}", d.dir}, {"{src}", d.src}}) {
    for (size_t at = arg.find(key); at != std::string::npos; at = arg.find(key, at + value.size()))
      arg.replace(at, key.size(), value);
  }
  return arg;
}

// The house rule's shape of a refusal: exactly one line on stderr, "nxtmap: ...", nothing a terminal acts on.
std::string refusalShape(const std::string& err) {
  if (err.empty() || err.back() != '\n') return "stderr is not one whole line";
  const std::string line = err.substr(0, err.size() - 1);
  if (line.find('\n') != std::string::npos) return "stderr has more than one line";
  if (line.rfind("nxtmap: ", 0) != 0) return "stderr does not start with 'nxtmap: '";
  for (unsigned char c : line) {
    if (c < 0x20 || c == 0x7f) return "stderr holds a control character";
  }
  return "";
}

class Adversarial : public ::testing::TestWithParam<AdversarialCase> {};

TEST_P(Adversarial, RefusedCleanlyOrWorks) {
  const AdversarialCase& c = GetParam();
  test::TempDir tmp("adv_" + c.name);
  const CaseDirs dirs{tmp.path("case"), NXTMAP_SOURCE_DIR};
  fs::create_directories(dirs.path("cwd"));
  fs::create_directories(tmp.path("scratch"));
  if (c.setup) c.setup(dirs);
  const TreeSnapshot before = TreeSnapshot::of(dirs.dir);
  struct stat devFull {};
  const bool hadDevFull = ::stat("/dev/full", &devFull) == 0 && S_ISCHR(devFull.st_mode);

  std::vector<std::string> args;
  for (const std::string& a : c.args) args.push_back(substitute(a, dirs));
  const ChildResult r =
      runChild(cliUnderTest(), args, dirs.path("cwd"), substitute(c.stdinText, dirs), tmp.path("scratch"), c.timeoutS);

  ASSERT_FALSE(r.timedOut) << "hung: still running after " << c.timeoutS << " s; stderr: " << r.err;
  ASSERT_FALSE(r.signalled) << "killed by signal " << r.signal << "; stderr: " << r.err;
  EXPECT_LE(r.peakRssKiB, kMemoryBoundKiB) << "peak memory " << r.peakRssKiB / 1024 << " MiB";
  if (c.works) {
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const std::string& f : c.creates) EXPECT_TRUE(fs::exists(dirs.path(f))) << f << " was not written";
  } else {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(refusalShape(r.err), "") << "stderr: [" << r.err << "]";
    EXPECT_EQ(TreeSnapshot::of(dirs.dir).differenceFrom(before), "") << "a refused command changed the files";
  }
  struct stat after {};
  if (hadDevFull) {
    EXPECT_TRUE(::stat("/dev/full", &after) == 0 && S_ISCHR(after.st_mode)) << "/dev/full is gone";
  }
  if (c.check) {
    EXPECT_EQ(c.check(dirs), "");
  }
}

std::string caseName(const ::testing::TestParamInfo<AdversarialCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Table, Adversarial, ::testing::ValuesIn(allCases()), caseName);

TEST(AdversarialTable, NamesAreUniqueAndTheTableIsNotEmpty) {
  std::set<std::string> names;
  const auto all = allCases();
  for (const AdversarialCase& c : all) EXPECT_TRUE(names.insert(c.name).second) << "two cases named " << c.name;
  EXPECT_GE(all.size(), 100u);
}

}  // namespace
}  // namespace nxtmap::adversarial
