// ElfImage::load reads only a regular file of at most kMaxElfBytes, checked before reading: a device
// (/dev/zero), a folder, a pipe or an oversized file gets one clear message at once.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>

#include "host/emu/ElfImage.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::emu {
namespace {

using ::nxtmap::test::TempDir;

struct BadFirmware {
  const char* label;
  std::function<std::string(const TempDir&)> make;  // returns the firmware's path
  const char* expected;                             // part of the message
};

class ElfImageBad : public ::testing::TestWithParam<BadFirmware> {};

TEST_P(ElfImageBad, IsRefusedAtOnceWithAClearMessage) {
  TempDir tmp("elfimage");
  const std::string path = GetParam().make(tmp);
  const auto start = std::chrono::steady_clock::now();
  const ElfLoad l = ElfImage::load(path);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  EXPECT_FALSE(l.image);
  EXPECT_EQ(l.error.rfind(path + ": ", 0), 0u) << l.error;
  EXPECT_NE(l.error.find(GetParam().expected), std::string::npos) << l.error;
}

INSTANTIATE_TEST_SUITE_P(
    Variants, ElfImageBad,
    ::testing::Values(BadFirmware{"devZero", [](const TempDir&) { return std::string("/dev/zero"); },
                                  "is a device, not a regular file"},
                      BadFirmware{"linkToDevZero",
                                  [](const TempDir& d) {
                                    std::filesystem::create_symlink("/dev/zero", d.path("fw.elf"));
                                    return d.path("fw.elf");
                                  },
                                  "is a device"},
                      BadFirmware{"folder",
                                  [](const TempDir& d) {
                                    std::filesystem::create_directory(d.path("fw.elf"));
                                    return d.path("fw.elf");
                                  },
                                  "is a directory, not a file"},
                      BadFirmware{"pipe",
                                  [](const TempDir& d) {
                                    EXPECT_EQ(::mkfifo(d.path("fw.elf").c_str(), 0600), 0);
                                    return d.path("fw.elf");
                                  },
                                  "is a pipe"},
                      BadFirmware{"oversized",
                                  [](const TempDir& d) {
                                    const std::string path = d.write("fw.elf",
                                                                     "\x7f"
                                                                     "ELF");
                                    EXPECT_EQ(::truncate(path.c_str(), static_cast<off_t>(kMaxElfBytes) + 1), 0);
                                    return path;
                                  },
                                  "larger than 8 MiB, the largest firmware file accepted"},
                      BadFirmware{"missing", [](const TempDir& d) { return d.path("none.elf"); },
                                  "cannot open firmware file (No such file or directory)"},
                      BadFirmware{"empty", [](const TempDir& d) { return d.write("fw.elf", ""); }, "not an ELF file"}),
    [](const ::testing::TestParamInfo<BadFirmware>& p) { return std::string(p.param.label); });

}  // namespace
}  // namespace nxtmap::emu
