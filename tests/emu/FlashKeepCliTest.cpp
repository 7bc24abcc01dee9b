// `nxtmap emulate --flash-keep FILE`: the emulated brick's flash from one run to the next, as a brick keeps it
// while switched off. Our firmware keeps what it learnt of its wheels there (WheelRecord) and tells the PC at
// once on the next start; a file that is no kept flash is refused before anything runs, and left as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "host/emu/FlashState.hpp"
#include "tests/cli/CliTestSupport.hpp"

namespace nxtmap::cli::test {
namespace {

const std::string kRoom = "worlds/seed-appendix-a/occupancy-120.map";
const std::string kBrick = shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf");

std::string emulate(const std::string& args) {
  return "emulate " + kRoom + " --start 1,20 --firmware " + kBrick + args;
}

// A WheelRecord written into a kept flash file at the record's page, as the brick would.
void storeWheels(const std::string& file, const WheelCalibration& w) {
  std::string error;
  std::optional<std::vector<uint8_t>> flash = emu::readFlashState(file, error);
  ASSERT_TRUE(flash) << file << ": " << error;
  emu::storeWheels(*flash, w);
  ASSERT_TRUE(emu::writeFlashState(file, *flash, error)) << error;
}

TEST(FlashKeepCli, RefusesWhatIsNoKeptFlashAndLeavesItAsItWas) {
  TempDir dir("flashkeep");
  const std::string small = dir.path("small.bin");
  std::ofstream(small) << "not a flash";
  const RunOutput r = runCli(emulate(" --seconds 1 --flash-keep " + shellQuote(small)));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("not a kept flash (11 bytes, 262144 expected)"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.out, "") << "nothing ran";
  EXPECT_EQ(readFile(small), "not a flash");
  const RunOutput folder = runCli(emulate(" --seconds 1 --flash-keep " + shellQuote(dir.path(""))));
  EXPECT_EQ(folder.exitCode, 2) << folder.err;
  EXPECT_EQ(lines(folder.err).size(), 1u) << folder.err;
  const RunOutput nowhere = runCli(emulate(" --seconds 1 --flash-keep /nonexistent/dir/flash.bin"));
  EXPECT_EQ(nowhere.exitCode, 2) << nowhere.err;
  EXPECT_EQ(lines(nowhere.err).size(), 1u) << nowhere.err;
}

// A new file: the brick finds nothing kept, and the file holds its whole flash afterwards. Wheels stored there
// are what the brick tells the PC from its first status on, before any run (read from its flash at start-up).
TEST(FlashKeepCli, TheBrickStartsWithTheWheelsItsFlashKept) {
  TempDir dir("flashkeep");
  const std::string file = dir.path("brick.flash");
  const RunOutput first = runCli(emulate(" --seconds 2 --enter-at -1 --flash-keep " + shellQuote(file)));
  EXPECT_EQ(first.exitCode, 0) << first.err;
  EXPECT_NE(first.out.find("flash kept       " + file + ": new (the brick starts with nothing kept)"),
            std::string::npos)
      << first.out;
  EXPECT_NE(first.out.find("wheels in flash  none\n"), std::string::npos) << first.out;
  ASSERT_EQ(std::filesystem::file_size(file), emu::kFlashSize);

  WheelCalibration w;
  w.driftUradPerM = -33500;  // -1.92 deg/m
  w.turnPpm = 17800;         // +1.78 %
  w.driftVariance = 4000000;
  w.turnVariance = 250000;
  storeWheels(file, w);
  const RunOutput second =
      runCli(emulate(" --seconds 3 --enter-at -1 --until time --score --flash-keep " + shellQuote(file)));
  EXPECT_EQ(second.exitCode, 0) << second.err;
  EXPECT_NE(second.out.find(": wheels drift -1.92 deg/m, turns +1.78 %\n"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("wheels reported  drift -1.92 deg/m, turns +1.78 %"), std::string::npos) << second.out;
  EXPECT_NE(second.out.find("wheels in flash  drift -1.92 deg/m, turns +1.78 %"), std::string::npos) << second.out;

  const RunOutput forgotten = runCli(emulate(" --seconds 3 --enter-at -1 --until time --score"));
  EXPECT_NE(forgotten.out.find("wheels reported  drift +0.00 deg/m, turns +0.00 %"), std::string::npos)
      << "without the kept flash the brick knows nothing of its wheels\n"
      << forgotten.out;
}

// A whole room under uncalibrated wheels: what the brick learnt is in its flash at the end, as it told the PC.
TEST(FlashKeepEndToEnd, ARunKeepsWhatItLearntOfTheWheels) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole room at emulation speed: make test runs this from the Release build";
#endif
  TempDir dir("flashkeep");
  const std::string file = dir.path("brick.flash");
  const RunOutput r =
      runCli(emulate(" --noise nxt-uncalibrated --start-jitter 10 --seed 3 --score --flash-keep " + shellQuote(file)));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("end              exploration done"), std::string::npos) << r.out;
  const auto after = [&](const std::string& key) {
    const size_t at = r.out.find(key);
    return at == std::string::npos ? std::string() : r.out.substr(at + key.size(), 32);  // "drift ..., turns ... %"
  };
  const std::string kept = after("wheels in flash  ");
  EXPECT_EQ(kept.rfind("drift ", 0), 0u) << r.out;
  EXPECT_NE(kept.rfind("drift +0.00 deg/m, turns +0.00 %", 0), 0u) << "something was learnt\n" << r.out;
  EXPECT_EQ(kept, after("wheels reported  ")) << r.out;
}

}  // namespace
}  // namespace nxtmap::cli::test
