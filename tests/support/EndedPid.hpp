#pragma once
// Test helper: the pid of a process that has ended (forked, exited at once, reaped), for the names a killed
// writer leaves behind ("<target>.saving-<pid>", "<target>.tmp-<pid>-<n>").
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace nxtmap::test {

inline pid_t endedPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

}  // namespace nxtmap::test
