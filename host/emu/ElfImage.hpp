// ElfImage: a firmware ELF32 (ARM, little-endian) loaded as the chip would hold it: every PT_LOAD segment
// at its load address (LMA), so .data's initial image sits in flash. Symbols from .symtab by name, and
// its functions by address (for profiles).
// A file named *.bin is a raw flash image for kFlashBase instead (at most kFlashSize bytes, no symbols):
// what users have for LEGO's and other firmwares.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nxtmap::emu {

constexpr uint32_t kFlashBase = 0x00100000;
constexpr uint32_t kFlashSize = 0x00040000;  // 256 KiB
constexpr uint32_t kRamBase = 0x00200000;
constexpr uint32_t kRamSize = 0x00010000;  // 64 KiB
// Largest firmware file read, bytes, checked before reading (only regular files are read): 32 times the
// flash, room for the symbols and debug information of an image that fits it (ours, built with -g: 0.6 MiB).
constexpr size_t kMaxElfBytes = size_t{8} << 20;

struct ElfLoad;

// A function of the image: [address, address + size), the Thumb bit cleared.
struct FunctionSymbol {
  uint32_t address = 0;
  uint32_t size = 0;
  std::string name;  // as in the ELF (mangled)
};

class ElfImage {
 public:
  // A regular file of at most kMaxElfBytes; otherwise, or when it is no ARM ELF that fits the chip, an error.
  static ElfLoad load(const std::string& path);

  const std::vector<uint8_t>& flash() const { return flash_; }  // kFlashSize bytes, 0xFF where unused
  const std::vector<uint8_t>& ram() const { return ram_; }      // kRamSize bytes loaded into RAM (RAM-run images)
  // The [offset, offset + size) ranges of RAM the ELF loads (offsets from kRamBase).
  const std::vector<std::pair<uint32_t, uint32_t>>& ramSegments() const { return ramSegments_; }
  bool hasFlashCode() const { return flashUsed_ > 0; }
  uint32_t flashUsed() const { return flashUsed_; }  // bytes from kFlashBase to the end of the last segment
  uint32_t entry() const { return entry_; }
  std::optional<uint32_t> symbol(const std::string& name) const;
  // The first of the names that exists.
  std::optional<uint32_t> firstSymbol(std::initializer_list<const char*> names) const;
  // The function holding `address`, or nullptr (a raw image, or code no function symbol covers).
  const FunctionSymbol* functionAt(uint32_t address) const;
  const std::string& path() const { return path_; }
  bool rawFlash() const { return raw_; }  // loaded from a raw .bin image: no symbols
  // The pages above the image (from flashUsed() rounded up to a 256-byte page) taken from `saved` (a whole
  // kFlashSize flash, FlashState): what a firmware stored in its flash survives, as over a power cycle.
  void keepPagesFrom(const std::vector<uint8_t>& saved);

 private:
  std::string path_;
  std::vector<uint8_t> flash_ = std::vector<uint8_t>(kFlashSize, 0xFF);
  std::vector<uint8_t> ram_ = std::vector<uint8_t>(kRamSize, 0x00);
  std::vector<std::pair<uint32_t, uint32_t>> ramSegments_;
  uint32_t flashUsed_ = 0;
  uint32_t entry_ = 0;
  bool raw_ = false;
  std::map<std::string, uint32_t> symbols_;
  std::vector<FunctionSymbol> functions_;  // sorted by address
  friend struct ElfLoader;
};

struct ElfLoad {
  std::optional<ElfImage> image;
  std::string error;  // names the file and the problem
};

}  // namespace nxtmap::emu
