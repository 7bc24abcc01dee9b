#pragma once
// The one check hook of the core. Its policy is set per build: on the host a failed check
// fails the test (via a handler the test harness installs); on the brick the firmware's handler
// stops the motors and shows the reason on the LCD. Checks guard invariants, never user input.
namespace nxtmap {

using CheckHandler = void (*)(const char* file, int line, const char* what);

// Installs the handler; returns the previous one. Default: spin forever (a hung brick is safe:
// the firmware watchdog and motor-silence guard stop the wheels).
CheckHandler setCheckHandler(CheckHandler handler);
[[noreturn]] void checkFailed(const char* file, int line, const char* what);

}  // namespace nxtmap

#define NXTMAP_CHECK(cond) ((cond) ? static_cast<void>(0) : ::nxtmap::checkFailed(__FILE__, __LINE__, #cond))
