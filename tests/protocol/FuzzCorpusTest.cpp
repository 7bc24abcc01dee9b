// Replays every input the fuzzer kept (fuzz/corpus) through the fuzz target's body: the
// regression test for whatever `make fuzz` found.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/ProtocolFuzzBody.hpp"

namespace nxtmap {
namespace {

TEST(FuzzCorpus, EveryKeptInputPassesTheFuzzTargetsProperties) {
  const std::filesystem::path dir = std::filesystem::path(NXTMAP_SOURCE_DIR) / "fuzz" / "corpus";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  size_t inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const char* bad = fuzz::runProtocolInput(data.data(), data.size());
    EXPECT_EQ(bad, nullptr) << entry.path().filename() << ": " << (bad ? bad : "");
    ++inputs;
  }
  EXPECT_GE(inputs, 8u);
}

}  // namespace
}  // namespace nxtmap
