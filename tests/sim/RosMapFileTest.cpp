// RosMapFile: the one ROS map_server reader. Numbers are range-checked before any use (resolution, origin),
// the YAML and its image are read only as regular files of a bounded size.
#include "host/sim/RosMapFile.hpp"

#include "host/sim/PgmImage.hpp"

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

const std::string kPgm = std::string("P5\n2 2\n255\n") + '\0' + '\xfe' + '\xfe' + '\xcd';  // occ, free / free, unknown

// A map_server YAML naming m.pgm; `replace` ("key: value") replaces that key's line or is appended.
std::string yamlWith(const std::string& replace) {
  std::string lines[] = {"image: m.pgm", "resolution: 0.1",       "origin: [0.0, 0.0, 0.0]",
                         "negate: 0",    "occupied_thresh: 0.65", "free_thresh: 0.196"};
  const std::string key = replace.substr(0, replace.find(':') + 1);
  bool replaced = false;
  std::string out;
  for (std::string& l : lines) {
    if (!key.empty() && l.rfind(key, 0) == 0) {
      l = replace;
      replaced = true;
    }
    out += l + "\n";
  }
  return replaced ? out : out + replace + "\n";
}

struct BadRos {
  const char* label;
  std::function<std::string(const TempDir&)> make;  // writes the files, returns the YAML's path
  const char* expected;                             // part of the message
};

std::function<std::string(const TempDir&)> with(const std::string& line) {
  return [line](const TempDir& d) {
    d.write("m.pgm", kPgm);
    return d.write("m.yaml", yamlWith(line));
  };
}

class RosMapFileBad : public ::testing::TestWithParam<BadRos> {};

TEST_P(RosMapFileBad, IsRefusedAtOnceWithAClearMessage) {
  TempDir tmp("rosmapfile");
  const std::string path = GetParam().make(tmp);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  const std::optional<RosMapFile> map = readRosMapFile(path, error);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(map);
  EXPECT_LT(seconds, 2.0);
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_NE(error.find(GetParam().expected), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

const char* const kResolutionNumber = "'resolution' must be a number > 0, in 0.01 .. 10 m per cell";
const char* const kResolutionRange = "is out of range: it must be in 0.01 .. 10 m per cell";
const char* const kOriginNumbers = "'origin' must be [x, y, yaw] (three numbers)";
const char* const kOriginRange = "is out of range: x and y must lie within +-100000 m, yaw within +-6.3 rad";

INSTANTIATE_TEST_SUITE_P(
    Variants, RosMapFileBad,
    ::testing::Values(BadRos{"resolutionZero", with("resolution: 0"), kResolutionNumber},
                      BadRos{"resolutionNegative", with("resolution: -0.1"), kResolutionNumber},
                      BadRos{"resolutionNan", with("resolution: .nan"), kResolutionNumber},
                      BadRos{"resolutionInf", with("resolution: .inf"), kResolutionNumber},
                      BadRos{"resolutionText", with("resolution: fine"), kResolutionNumber},
                      BadRos{"resolutionList", with("resolution: [0.1]"), kResolutionNumber},
                      BadRos{"resolutionDenormal", with("resolution: 1e-300"), kResolutionRange},
                      BadRos{"resolutionBelowACentimetre", with("resolution: 0.004"), kResolutionRange},
                      BadRos{"resolutionHuge", with("resolution: 1e300"), kResolutionRange},
                      BadRos{"resolutionAbove10m", with("resolution: 10.5"), kResolutionRange},
                      BadRos{"originNan", with("origin: [.nan, 0.0, 0.0]"), kOriginNumbers},
                      BadRos{"originInf", with("origin: [0.0, .inf, 0.0]"), kOriginNumbers},
                      BadRos{"originYawNegInf", with("origin: [0.0, 0.0, -.inf]"), kOriginNumbers},
                      BadRos{"originShort", with("origin: [0.0]"), kOriginNumbers},
                      BadRos{"originScalar", with("origin: 5"), kOriginNumbers},
                      BadRos{"originFarX", with("origin: [100000.5, 0.0, 0.0]"), kOriginRange},
                      BadRos{"originFarY", with("origin: [0.0, -1e300, 0.0]"), kOriginRange},
                      BadRos{"originYawTooBig", with("origin: [0.0, 0.0, 7]"), kOriginRange},
                      BadRos{"negateText", with("negate: perhaps"), "'negate' must be 0 or 1"},
                      BadRos{"thresholdNan", with("free_thresh: .nan"), "must be numbers"},
                      BadRos{"imageDevZero",
                             [](const TempDir& d) {
                               std::filesystem::create_symlink("/dev/zero", d.path("zero.pgm"));
                               return d.write("m.yaml", yamlWith("image: zero.pgm"));
                             },
                             "zero.pgm: is a device, not a regular file"},
                      BadRos{"imageFolder", [](const TempDir& d) { return d.write("m.yaml", yamlWith("image: .")); },
                             "is a directory, not a file"},
                      BadRos{"imagePipe",
                             [](const TempDir& d) {
                               EXPECT_EQ(::mkfifo(d.path("fifo.pgm").c_str(), 0600), 0);
                               return d.write("m.yaml", yamlWith("image: fifo.pgm"));
                             },
                             "fifo.pgm: is a pipe"},
                      BadRos{"imageHuge",
                             [](const TempDir& d) {
                               EXPECT_EQ(
                                   ::truncate(d.write("big.pgm", "").c_str(), static_cast<off_t>(kMaxPgmBytes) + 1), 0);
                               return d.write("m.yaml", yamlWith("image: big.pgm"));
                             },
                             "big.pgm: larger than 100 MiB, the largest image file accepted"},
                      BadRos{"yamlDevZero",
                             [](const TempDir& d) {
                               std::filesystem::create_symlink("/dev/zero", d.path("zero.yaml"));
                               return d.path("zero.yaml");
                             },
                             "is a device, not a regular file"},
                      BadRos{"yamlFolder",
                             [](const TempDir& d) {
                               std::filesystem::create_directory(d.path("room.yaml"));
                               return d.path("room.yaml");
                             },
                             "is a directory, not a file"},
                      BadRos{"yamlHuge",
                             [](const TempDir& d) {
                               const std::string path = d.write("m.yaml", yamlWith("labels:"));
                               EXPECT_EQ(::truncate(path.c_str(), static_cast<off_t>(kMaxRosYamlBytes) + 1), 0);
                               return path;
                             },
                             "larger than 1 MiB, the largest file accepted"},
                      BadRos{"yamlDeeplyNested", with("labels: " + std::string(100000, '[')), "m.yaml: "}),
    [](const ::testing::TestParamInfo<BadRos>& p) { return std::string(p.param.label); });

TEST(RosMapFile, AcceptsTheBoundsAndReadsTheCellsOriginAndLabels) {
  TempDir tmp("rosmapfile_ok");
  tmp.write("m.pgm", kPgm);
  struct Good {
    const char* resolution;
    const char* origin;
    double res, x, y, yaw;
  };
  for (const Good& g : {Good{"0.01", "[100000, -100000, 6.3]", 0.01, 100000, -100000, 6.3},
                        Good{"10", "[-100000, 100000, -6.3]", 10, -100000, 100000, -6.3},
                        Good{"0.05", "[-1.5, 2.25, 0.5]", 0.05, -1.5, 2.25, 0.5}}) {
    const std::string yaml = "image: m.pgm\nresolution: " + std::string(g.resolution) + "\norigin: " + g.origin +
                             "\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nlabels:\n  door: [1, 0]\n"
                             "  rug: [0, 0, 2, 2]\n";
    std::string error;
    const std::optional<RosMapFile> m = readRosMapFile(tmp.write("m.yaml", yaml), error);
    ASSERT_TRUE(m) << error;
    EXPECT_EQ(m->width, 2);
    EXPECT_EQ(m->height, 2);
    EXPECT_DOUBLE_EQ(m->resolutionM, g.res);
    EXPECT_DOUBLE_EQ(m->originX, g.x);
    EXPECT_DOUBLE_EQ(m->originY, g.y);
    EXPECT_DOUBLE_EQ(m->originYaw, g.yaw);
    EXPECT_EQ(m->cells, (std::vector<RosCell>{RosCell::Occupied, RosCell::Free, RosCell::Free, RosCell::Unknown}));
    ASSERT_EQ(m->labels.size(), 2u);
    EXPECT_EQ(m->labels[0].name, "door");
    EXPECT_EQ(m->labels[1].width, 2);
  }
}

}  // namespace
}  // namespace nxtmap::sim
