// InputFile: only regular files are read, and only up to the stated size, checked before reading: a
// directory, a device (/dev/zero), a pipe or an oversized file gets one clear message at once.
#include "host/sim/InputFile.hpp"

#include "tests/sim/SimTestSupport.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>

namespace nxtmap::sim {
namespace {

using test::TempDir;

constexpr size_t kBound = 64;  // bytes, the bound of the table's reads

// A file of `bytes` bytes that takes no disk space (a sparse file): fstat sees its size at once.
std::string sparseFile(const TempDir& tmp, const std::string& name, off_t bytes) {
  const std::string path = tmp.write(name, "");
  EXPECT_EQ(::truncate(path.c_str(), bytes), 0);
  return path;
}

struct BadInput {
  const char* label;
  std::function<std::string(const TempDir&)> make;  // returns the path to read
  const char* expected;                             // part of the message
};

class InputFileBad : public ::testing::TestWithParam<BadInput> {};

TEST_P(InputFileBad, IsRefusedAtOnceWithAClearMessage) {
  TempDir tmp("inputfile");
  const std::string path = GetParam().make(tmp);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  const std::optional<std::string> bytes = readInputFile(path, kBound, "image file", error);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(bytes);
  EXPECT_LT(seconds, 2.0);
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_NE(error.find(GetParam().expected), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Variants, InputFileBad,
    ::testing::Values(
        BadInput{"missing", [](const TempDir& d) { return d.path("absent.pgm"); },
                 "cannot open image file (No such file or directory)"},
        BadInput{"directory", [](const TempDir& d) { return d.path(); }, "is a directory, not a file"},
        BadInput{"devZero", [](const TempDir&) { return std::string("/dev/zero"); }, "is a device, not a regular file"},
        BadInput{"linkToDevZero",
                 [](const TempDir& d) {
                   std::filesystem::create_symlink("/dev/zero", d.path("zero.pgm"));
                   return d.path("zero.pgm");
                 },
                 "is a device"},
        BadInput{"pipeWithoutWriter",
                 [](const TempDir& d) {
                   EXPECT_EQ(::mkfifo(d.path("fifo.pgm").c_str(), 0600), 0);
                   return d.path("fifo.pgm");
                 },
                 "is a pipe, not a regular file"},
        BadInput{"oneByteTooMany", [](const TempDir& d) { return d.write("big.pgm", std::string(kBound + 1, 'x')); },
                 "larger than 64 bytes, the largest image file accepted"},
        BadInput{"hugeSparse", [](const TempDir& d) { return sparseFile(d, "huge.pgm", off_t{1} << 30); },
                 "larger than 64 bytes"}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return std::string(p.param.label); });

TEST(InputFile, ReadsARegularFileUpToTheBoundExactly) {
  TempDir tmp("inputfile_ok");
  std::string error;
  const std::string full(kBound, '\0');
  const std::optional<std::string> bytes = readInputFile(tmp.write("full.pgm", full), kBound, "image file", error);
  ASSERT_TRUE(bytes) << error;
  EXPECT_EQ(*bytes, full);
  const std::optional<std::string> empty = readInputFile(tmp.write("empty.pgm", ""), kBound, "image file", error);
  ASSERT_TRUE(empty) << error;
  EXPECT_EQ(*empty, "");
}

TEST(InputFile, BoundsStatedInMiB) {
  TempDir tmp("inputfile_mib");
  std::string error;
  const std::string path = sparseFile(tmp, "big.map", (off_t{3} << 20) + 1);
  EXPECT_FALSE(readInputFile(path, size_t{3} << 20, "file", error));
  EXPECT_NE(error.find("larger than 3 MiB, the largest file accepted"), std::string::npos) << error;
}

}  // namespace
}  // namespace nxtmap::sim
