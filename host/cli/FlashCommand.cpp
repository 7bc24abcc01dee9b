#include "host/cli/FlashCommand.hpp"

#include <CLI/CLI.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "host/cli/Errors.hpp"

namespace nxtmap::cli {
namespace {

// Runs fwflash on the image; returns its exit status and output (stdout and stderr).
int runFwflash(const std::string& image, std::string& output) {
  const char* tool = std::getenv("NXTMAP_FWFLASH");  // tests point this at a stand-in
  const std::string exe = tool != nullptr ? tool : "fwflash";
  std::string quoted = "'";
  for (char c : image) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  FILE* p = ::popen((exe + " " + quoted + " 2>&1").c_str(), "r");
  if (p == nullptr) return -1;
  std::array<char, 256> buf{};
  while (std::fgets(buf.data(), buf.size(), p) != nullptr) output += buf.data();
  const int status = ::pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

CLI::App* addFlashCommand(CLI::App& app, FlashOptions& o) {
  CLI::App* c = app.add_subcommand("flash", "write a firmware image to a brick in SAM-BA mode (USB, libnxt fwflash)");
  c->add_option("image", o.image, "the firmware image (.bin, at most 262144 bytes)");
  c->add_flag("--restore", o.restore, std::string("put LEGO's firmware back (") + kLegoFirmwarePath + ")");
  return c;
}

int runFlash(const FlashOptions& o) {
  if (o.restore == !o.image.empty()) throw CliError("flash: give either FILE.bin or --restore");
  const std::string image = o.restore ? std::string(kLegoFirmwarePath) : o.image;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(image, ec)) {
    if (o.restore)
      throw CliError(std::string("flash: ") + kLegoFirmwarePath + " is missing: install Debian's nxt-firmware package");
    throw CliError("flash: " + image + " is not a file");
  }
  const auto size = std::filesystem::file_size(image, ec);
  if (ec || size == 0) throw CliError("flash: " + image + " is empty or unreadable");
  if (static_cast<long>(size) > kFlashBytes) {
    throw CliError("flash: " + image + " has " + std::to_string(size) + " bytes, more than the NXT's " +
                   std::to_string(kFlashBytes) + " bytes of flash");
  }
  std::string output;
  const int rc = runFwflash(image, output);
  if (rc == 0) {
    std::cout << "flashed " << image << " (" << size << " bytes); the brick restarts with it\n";
    return kExitOk;
  }
  if (rc == 127 || rc == -1) throw CliError("flash: fwflash was not found: install Debian's libnxt package");
  if (output.find("NXT not found") != std::string::npos) {
    printError(
        "flash: no NXT brick waiting in SAM-BA mode on USB: connect it by USB and hold the reset button "
        "(the pinhole under the USB port) for 5 seconds until it ticks, then try again");
    return 1;
  }
  std::string firstLine = output.substr(0, output.find('\n'));
  printError("flash: fwflash failed (exit " + std::to_string(rc) + "): " + firstLine);
  return 1;
}

}  // namespace nxtmap::cli
