// Saving a ROS map (YAML + PGM): a write error keeps both old files byte for byte and names the reason;
// a target that is not a regular file is refused before either file is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "host/mapio/MapFiles.hpp"
#include "tests/support/FileSizeLimit.hpp"
#include "tests/support/FileText.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::mapio {
namespace {
namespace fs = std::filesystem;

TEST(MapSave, AWriteErrorKeepsBothOldFilesAndNamesTheReason) {
  test::TempDir t("mapsave_error");
  std::string error;
  ASSERT_TRUE(saveRosMap(OccupancyMap(4, 3, Occupancy::Free), t.path("room.yaml"), error)) << error;
  const std::string yaml = test::readWholeFile(t.path("room.yaml")), pgm = test::readWholeFile(t.path("room.pgm"));
  {
    const test::FileSizeLimit limit(1024);  // the 100 x 100 PGM (10 000 bytes) does not fit
    EXPECT_FALSE(saveRosMap(OccupancyMap(100, 100, Occupancy::Occupied), t.path("room.yaml"), error));
  }
  EXPECT_NE(error.find("room.pgm: File too large"), std::string::npos) << error;
  EXPECT_EQ(test::readWholeFile(t.path("room.yaml")), yaml);
  EXPECT_EQ(test::readWholeFile(t.path("room.pgm")), pgm);
  EXPECT_EQ(test::folderEntries(t.path()), (std::vector<std::string>{"room.pgm", "room.yaml"}));
}

TEST(MapSave, ATargetThatIsNotAFileIsRefusedBeforeAnythingIsWritten) {
  test::TempDir t("mapsave_refuse");
  fs::create_directories(t.path("room.pgm"));
  std::string error;
  EXPECT_FALSE(saveRosMap(OccupancyMap(4, 3, Occupancy::Free), t.path("room.yaml"), error));
  EXPECT_NE(error.find("room.pgm: it is a directory"), std::string::npos) << error;
  EXPECT_EQ(test::folderEntries(t.path()), std::vector<std::string>{"room.pgm"});
  EXPECT_FALSE(saveRosMap(OccupancyMap(4, 3, Occupancy::Free), t.path("none/room.yaml"), error));
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
  EXPECT_EQ(test::folderEntries(t.path()), std::vector<std::string>{"room.pgm"});
}

}  // namespace
}  // namespace nxtmap::mapio
