// `nxtmap emulate` from the outside: bad input gives one clear line and exit code 2; a firmware fault
// exit code 1 with the report; a good run prints its measurements and writes the LCD picture.
#include "tests/cli/CliTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

namespace nxtmap::cli::test {
namespace {

const std::string kRoom = "worlds/seed-appendix-a/occupancy-120.map";

std::string probe(const std::string& name) { return std::string(NXTMAP_EMU_PROBE_DIR) + "/" + name + ".elf"; }

void expectUsageError(const RunOutput& r, const std::string& needle) {
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("nxtmap: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
}

TEST(EmulateCli, RejectsBadOptionsWithOneLine) {
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --speed warp"), "--speed must be max or realtime");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --listen udp:1"),
                   "--listen must be tcp:127.0.0.1:PORT or pty");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --listen tcp:127.0.0.1:0"), "port must be 1..65535");
  expectUsageError(runCli("emulate " + kRoom + " --start 0,0"), "");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --noise loud"), "noise");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --seconds -3"), "--seconds");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --until soon"),
                   "--until must be explored, disconnect or time, not 'soon'");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --until disconnect"),
                   "--until disconnect needs --listen");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --score --listen pty"),
                   "--score listens on the radio itself: not with --listen");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --png x.png"),
                   "--png draws the scored map: it needs --score");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --score --png /nonexistent/dir/x.png"), "does not exist");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --firmware /nonexistent/fw.elf"), "make firmware");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --firmware README.md"), "not an ELF");
  expectUsageError(
      runCli("emulate " + kRoom + " --start 1,20 --firmware " + probe("boot") + " --lcd /nonexistent/dir/x.png"),
      "does not exist");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --firmware " + probe("boot") + " --lcd-every 1"),
                   "--lcd-every needs --lcd FILE.png");
  expectUsageError(runCli("emulate " + kRoom + " --start 1,20 --firmware " + probe("boot") +
                          " --lcd x.png --seconds 2 --lcd-every 3"),
                   "--lcd-every must lie in [0.001, --seconds]");
}

TEST(EmulateCli, FirmwareFaultEndsWithTheReportAndExitCode1) {
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --firmware " + probe("unmodelled"));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("unmodelled peripheral register at pc=0x"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("address=0xfffff240"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("end              FAULT"), std::string::npos) << r.out;
}

// --until time: only the time limit ends the run (a tool on the pty may leave and the next come).
TEST(EmulateCli, UntilTimeRunsToTheTimeLimit) {
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --until time --seconds 0.5 --firmware " +
                             shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("time limit reached"), std::string::npos) << r.out;
}

// A firmware without our symbols (LEGO's raw image) runs, and its RAM high-water is "not measured", not a number.
TEST(EmulateCli, ForeignFirmwareSaysItsRamIsNotMeasured) {
  const std::string lego = "/usr/share/nxt-firmware/nxt_firmware.bin";
  if (!std::filesystem::exists(lego)) GTEST_SKIP() << lego << " is absent (Debian package nxt-firmware, make deps)";
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --seconds 0.3 --firmware " + lego);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("has no nxtmap symbols"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("RAM high-water   not measured"), std::string::npos) << r.out;
}

#ifdef NXTMAP_EMU_FIRMWARE_DIR
// --score: the map that came over the radio, scored against the world. The published-geometry image on a
// published room without noise maps it as the host does (EndToEnd): every observable wall cell, no wrong cell,
// the robot where it believes it is; and a room the image cannot see whole is scored as it is (not 100 %).
TEST(EmulateCliEndToEnd, ScoreRatesTheMapThatCameOverTheRadio) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole room at emulation speed: make test runs this from the Release build";
#endif
  const std::string sim = shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf");
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --score --firmware " + sim);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("PC connected, stream mode"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("detected         100 % of the observable occupied cells"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrong cells      0 (unsafe free 0, phantom occupied 0)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lost             no"), std::string::npos) << r.out;
  TempDir dir("emuscore");
  const std::string png = dir.path("map.png");
  const RunOutput cut =
      runCli("emulate " + kRoom + " --start 1,20 --score --seconds 60 --firmware " + sim + " --png " + shellQuote(png));
  EXPECT_EQ(cut.exitCode, 0) << cut.err;
  EXPECT_NE(cut.out.find("wrote " + png), std::string::npos) << cut.out;
  const std::string bytes = readFile(png);
  ASSERT_GE(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  const auto be32 = [&](size_t at) {
    return (static_cast<uint8_t>(bytes[at]) << 24) | (static_cast<uint8_t>(bytes[at + 1]) << 16) |
           (static_cast<uint8_t>(bytes[at + 2]) << 8) | static_cast<uint8_t>(bytes[at + 3]);
  };
  EXPECT_EQ(be32(16), 22 * 8);  // IHDR: the room's 22 x 22 cells at 8 pixels a cell
  EXPECT_EQ(be32(20), 22 * 8);
  EXPECT_NE(cut.out.find("time limit reached"), std::string::npos) << cut.out;
  EXPECT_NE(cut.out.find("detected         "), std::string::npos) << cut.out;
  EXPECT_EQ(cut.out.find("detected         100 %"), std::string::npos) << "a minute of a room is not all of it\n"
                                                                       << cut.out;
}

// A brick set down off its cell's centre starts its explorer off the centre of the cell it believes in (the snap on
// the nearest walls): the map is scored on the grid the brick believed in, laid from the offset its first Status
// told, so it needs no more shift to fit the world than the run's own error, under a quarter of a cell (laid on the
// robot's centre instead, this seed's map needed one of half a cell: 97.6 % against 99.2 % shifted). The emulated
// runs are a draw on the image's timing: with one image this seed's map fitted unshifted, with the next 0.2 cells
// (seeds 8-12 with the same image: 0, 0, 0.2, 0.2, 0.2).
TEST(EmulateCliEndToEnd, ScoreLaysTheGridWhereTheBrickBelievedItsStartCell) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole room at emulation speed: make test runs this from the Release build";
#endif
  const std::string brick = shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf");
  const RunOutput r =
      runCli("emulate " + kRoom + " --start 1,20 --noise nxt --start-jitter 10 --seed 10 --score --firmware " + brick);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("end              exploration done: "), std::string::npos) << r.out;
  const auto after = [&](const std::string& key) {
    const size_t at = r.out.find(key);
    return at == std::string::npos
               ? std::string()
               : r.out.substr(at + key.size(), r.out.find_first_of(" %", at + key.size()) - at - key.size());
  };
  const size_t moved = r.out.find("moved ");
  ASSERT_NE(moved, std::string::npos) << r.out;
  double east = 9, north = 9;
  ASSERT_EQ(std::sscanf(r.out.c_str() + moved, "moved %lf,%lf cells to fit the world best", &east, &north), 2) << r.out;
  EXPECT_LT(std::abs(east), 0.25) << r.out;
  EXPECT_LT(std::abs(north), 0.25) << r.out;
  EXPECT_NE(after("detected         "), "") << r.out;
}

TEST(EmulateCli, RealFirmwareRunPrintsMeasurementsAndLcd) {
  TempDir dir("emucli");
  const std::string png = dir.path("lcd.png");
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --seconds 2 --firmware " +
                             shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf") + " --lcd " +
                             shellQuote(png) + " --lcd-every 0.5");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("end              time limit reached"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("RAM high-water   "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("not measured"), std::string::npos) << r.out;  // our ELF names the end of .bss
  EXPECT_NE(r.out.find("x real time"), std::string::npos) << r.out;
  EXPECT_EQ(readFile(png).substr(1, 3), "PNG");
  // --lcd-every 0.5 over 2 s: a picture at 0.5, 1.0, 1.5 and 2.0 s, numbered beside the last screen
  for (const char* n : {"lcd-0001.png", "lcd-0002.png", "lcd-0003.png", "lcd-0004.png"})
    EXPECT_EQ(readFile(dir.path(n)).substr(1, 3), "PNG") << n;
  EXPECT_FALSE(std::filesystem::exists(dir.path("lcd-0005.png")));
  EXPECT_NE(r.out.find("wrote 4 pictures"), std::string::npos) << r.out;
}

// --profile: the costliest sensor update's instructions by firmware function, the most first, none
// more than the update itself.
TEST(EmulateCli, ProfileNamesWhereTheCostliestSensorUpdateWent) {
  const RunOutput r = runCli("emulate " + kRoom + " --start 1,20 --seconds 20 --profile --firmware " +
                             shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const size_t at = r.out.find("costliest update ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const unsigned long long total = std::stoull(r.out.substr(at + 17));
  EXPECT_GT(total, 0u);
  std::istringstream rest(r.out.substr(r.out.find('\n', at) + 1));
  unsigned long long previous = total, named = 0;
  int listed = 0;
  for (std::string line; std::getline(rest, line) && line.rfind("  ", 0) == 0; ++listed) {
    const unsigned long long n = std::stoull(line);
    EXPECT_LE(n, previous) << line;
    previous = n;
    if (line.find("nxtmap::") != std::string::npos) named += n;
  }
  EXPECT_GE(listed, 3) << r.out;
  EXPECT_GT(named, 0u) << "the firmware's own functions, by name: " << r.out;
}

// The firmware drives the brick robot (20 cm cells, 16 x 18 cm body) through a hand-made room turned 10 degrees,
// with the measured sonar and wheels, set down off square: the emulated brick runs in the honest world too.
TEST(EmulateCli, RealFirmwareRunsInATurnedRoomWithTheMeasuredSensorsAndWheels) {
  const RunOutput r = runCli(
      "emulate worlds/rooms/square-turned.yaml --noise nxt --start-jitter 10 --seed 3 --seconds 110 "
      "--firmware " +
      shellQuote(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("robot brick (20 cm cells)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("noise nxt"), std::string::npos) << r.out;
  const size_t at = r.out.find("driven ");
  ASSERT_NE(at, std::string::npos) << r.out;
  // cm: it explored, not stood still (a fresh brick first measures its turns and squares to the walls: about 85 s)
  EXPECT_GT(std::stod(r.out.substr(at + 7)), 10.0) << r.out;
}
#endif

}  // namespace
}  // namespace nxtmap::cli::test
