// Errors: how the console reports bad input: one line "nxtmap: <message>" on stderr, exit code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace nxtmap::cli {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;  // bad input of any kind

// Bad input; the message is one line and names what was wrong.
class CliError : public std::runtime_error {
 public:
  explicit CliError(const std::string& message) : std::runtime_error(message) {}
};

// Writes "nxtmap: <message>" as a single line on stderr: newlines become spaces, and control characters and
// bytes that are not UTF-8 are shown as \xNN (report::escapeForTerminal), so a hostile name cannot drive the terminal.
void printError(const std::string& message);

}  // namespace nxtmap::cli
