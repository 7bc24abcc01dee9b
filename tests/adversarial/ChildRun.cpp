#include "tests/adversarial/ChildRun.hpp"

#include "tests/support/FileText.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace nxtmap::adversarial {
namespace {

// In the child: stdin, stdout, stderr onto the given files, then exec; never returns.
[[noreturn]] void execChild(const std::string& program, const std::vector<std::string>& args, const std::string& cwd,
                            const std::string& inPath, const std::string& outPath, const std::string& errPath) {
  const int in = ::open(inPath.c_str(), O_RDONLY);
  const int out = ::open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const int err = ::open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (in < 0 || out < 0 || err < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 ||
      ::chdir(cwd.c_str()) != 0)
    ::_exit(127);
  ::setpgid(0, 0);  // its own process group: a timeout kills whatever it started too
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(program.c_str(), argv.data());
  ::_exit(127);
}

}  // namespace

ChildResult runChild(const std::string& program, const std::vector<std::string>& args, const std::string& cwd,
                     const std::string& stdinText, const std::string& scratch, double timeoutS) {
  const std::string inPath = stdinText.empty() ? "/dev/null" : scratch + "/stdin";
  if (!stdinText.empty()) std::ofstream(inPath, std::ios::binary) << stdinText;
  const std::string outPath = scratch + "/stdout", errPath = scratch + "/stderr";
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) execChild(program, args, cwd, inPath, outPath, errPath);
  ::setpgid(pid, pid);

  ChildResult r;
  int status = 0;
  rusage usage{};
  const auto deadline = t0 + std::chrono::duration<double>(timeoutS);
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      r.timedOut = true;
      ::kill(-pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.peakRssKiB = usage.ru_maxrss;
  if (!r.timedOut && WIFSIGNALED(status)) {
    r.signalled = true;
    r.signal = WTERMSIG(status);
  } else if (!r.timedOut && WIFEXITED(status)) {
    r.exitCode = WEXITSTATUS(status);
  }
  ::kill(-pid, SIGKILL);  // anything it left running in its group
  r.out = test::readWholeFile(outPath);
  r.err = test::readWholeFile(errPath);
  return r;
}

}  // namespace nxtmap::adversarial
