// `nxtmap connect` waits a bounded time (defect #3 of issue 15): a --connect-timeout that is not
// a number of seconds in (0, 3600] is refused, and a TCP host that never answers (a listener
// that never accepts, or one that accepts and never speaks) ends in one clear line and exit 2
// within the timeout plus a margin.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "tests/cli/CliTestSupport.hpp"
#include "tests/link/LoopbackListener.hpp"

namespace nxtmap::cli::test {
namespace {

using link::test::LoopbackListener;

// Process start-up under the sanitizers, the last 20 ms poll slice and the runner's stop.
constexpr double kMarginS = 3.0;

struct TimedRun {
  RunOutput output;
  double seconds = 0;
};

// Runs `nxtmap <args>`, killed after 60 s should it hang (then it fails the time checks).
TimedRun runTimed(const std::string& args) {
  static int counter = 0;
  TempDir tmp("connect-timeout" + std::to_string(counter++));
  const std::string out = tmp.path("out"), err = tmp.path("err");
  const std::string cmd = "cd " + shellQuote(NXTMAP_SOURCE_DIR) + " && timeout -k 1 60 " + shellQuote(NXTMAP_CLI_PATH) +
                          " " + args + " < /dev/null > " + shellQuote(out) + " 2> " + shellQuote(err);
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  TimedRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.output.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.output.out = readFile(out);
  r.output.err = readFile(err);
  return r;
}

TEST(ConnectTimeout, ValuesThatAreNotSecondsInRangeAreRefused) {
  const std::string message = "nxtmap: connect: --connect-timeout must be a number of seconds in (0, 3600]";
  for (const char* value :
       {"nan", "NaN", "-nan", "inf", "-inf", "1e300", "3600.001", "3601", "0", "-0", "-1", "-1e300"}) {
    const TimedRun r = runTimed(std::string("connect tcp:127.0.0.1:1 --connect-timeout ") + value);
    EXPECT_EQ(r.output.exitCode, 2) << value;
    EXPECT_EQ(r.output.err, message + "\n") << value;
    EXPECT_LT(r.seconds, kMarginS) << value;
  }
}

TEST(ConnectTimeout, AHostThatNeverAcceptsEndsWithinTheTimeout) {
  const LoopbackListener host(LoopbackListener::Mode::NeverAccepts);
  ASSERT_TRUE(host.ready());
  const std::string link = "tcp:127.0.0.1:" + std::to_string(host.port());
  const TimedRun r = runTimed("connect " + link + " --connect-timeout 1.5");
  EXPECT_EQ(r.output.exitCode, 2);
  ASSERT_EQ(lines(r.output.err).size(), 1u) << r.output.err;
  EXPECT_EQ(r.output.err.rfind("nxtmap: connect: no answer from the brick on " + link + " within 1.5 s (", 0), 0u)
      << r.output.err;
  EXPECT_GE(r.seconds, 1.5);
  EXPECT_LT(r.seconds, 1.5 + kMarginS);
}

TEST(ConnectTimeout, AHostThatAcceptsAndNeverSpeaksEndsWithinTheTimeout) {
  const LoopbackListener host(LoopbackListener::Mode::AcceptsSilently);
  ASSERT_TRUE(host.ready());
  const std::string link = "tcp:127.0.0.1:" + std::to_string(host.port());
  const TimedRun r = runTimed("connect " + link + " --connect-timeout 1");
  EXPECT_EQ(r.output.exitCode, 2);
  EXPECT_EQ(r.output.err,
            "nxtmap: connect: no answer from the brick on " + link + " within 1 s (connected to " + link + ")\n");
  EXPECT_GE(r.seconds, 1.0);
  EXPECT_LT(r.seconds, 1.0 + kMarginS);
}

}  // namespace
}  // namespace nxtmap::cli::test
