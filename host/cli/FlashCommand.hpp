// `nxtmap flash FILE.bin` / `nxtmap flash --restore`: writes a firmware image to a brick waiting
// in SAM-BA mode over USB with Debian libnxt's fwflash; --restore puts LEGO's firmware back
// from Debian's nxt-firmware package (/usr/share/nxt-firmware/nxt_firmware.bin).
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace nxtmap::cli {

struct FlashOptions {
  std::string image;
  bool restore = false;
};

CLI::App* addFlashCommand(CLI::App& app, FlashOptions& options);
int runFlash(const FlashOptions& options);

// The LEGO firmware image from Debian's nxt-firmware package.
constexpr const char* kLegoFirmwarePath = "/usr/share/nxt-firmware/nxt_firmware.bin";
// A flashable NXT image: at most the 256 KiB of flash (our images are padded to exactly this).
constexpr long kFlashBytes = 262144;

}  // namespace nxtmap::cli
