// Saving a house: "DIR/" saves into DIR; a missing folder is refused and nothing is created; a staging
// directory left by a killed save is removed by the next save; a write error keeps the old house whole
// and names the reason.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "host/network/HouseFiles.hpp"
#include "tests/support/FileSizeLimit.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::network {
namespace {
namespace fs = std::filesystem;

Cell C(int x, int y) { return Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}; }

// Two rooms of `side` x `side` free cells joined by a gateway.
HouseNetwork house(int side) {
  HouseNetwork n;
  for (const char* name : {"hall", "kitchen"}) {
    RoomNode r;
    r.name = name;
    r.map = RoomMap(0, 0, side, side);
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) r.map.set(C(x, y), CellState::Free);
    }
    n.addRoom(r);
  }
  n.rooms()[1].toHouse = RoomTransform::fromPose(C(side, 0), Dir::East);
  n.addGateway(Gateway{0, 1, {C(side - 1, 0)}, {C(0, 0)}});
  return n;
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HouseSave, ATrailingSlashSavesIntoTheDirectory) {
  test::TempDir t("house_slash");
  for (const std::string& dir : {t.path("h") + "/", t.path("h") + "//", t.path("h") + "/"}) {  // new, then replaced
    std::string e;
    ASSERT_TRUE(saveHouse(house(3), 0.1, dir, e)) << dir << ": " << e;
    const HouseLoad l = loadHouse(t.path("h"));
    ASSERT_TRUE(l.network) << l.error;
    EXPECT_EQ(l.network->rooms().size(), 2u);
    EXPECT_EQ(entries(t.path()), std::vector<std::string>{"h"}) << "no staging directory left";
    EXPECT_EQ(entries(t.path("h")),
              (std::vector<std::string>{"hall.pgm", "hall.yaml", "house.yaml", "kitchen.pgm", "kitchen.yaml"}));
  }
}

TEST(HouseSave, AMissingFolderIsRefusedAndNothingIsCreated) {
  test::TempDir t("house_missing");
  std::string e;
  EXPECT_FALSE(saveHouse(house(3), 0.1, t.path("no/such/h"), e));
  EXPECT_NE(e.find("the folder " + t.path("no/such") + " does not exist"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_FALSE(checkHouseTarget(t.path("no/such/h/"), e));
  EXPECT_TRUE(fs::is_empty(t.path()));
}

TEST(HouseSave, AStagingDirectoryOfAKilledSaveIsRemovedByTheNextSave) {
  test::TempDir t("house_stale");
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);  // `child` is no longer alive: its staging is stale
  const std::string stale = "h.saving-" + std::to_string(child);
  t.write(stale + "/hall.yaml", "half written");
  std::string e;
  ASSERT_TRUE(saveHouse(house(3), 0.1, t.path("h"), e)) << e;
  EXPECT_EQ(entries(t.path()), std::vector<std::string>{"h"});
}

TEST(HouseSave, AWriteErrorKeepsTheOldHouseAndNamesTheReason) {
  test::TempDir t("house_error");
  std::string e;
  ASSERT_TRUE(saveHouse(house(3), 0.1, t.path("h"), e)) << e;
  const std::string before = slurp(t.path("h/house.yaml")) + slurp(t.path("h/hall.pgm"));
  {
    const test::FileSizeLimit limit(2048);  // a 60 x 60 room's PGM (3600 bytes) does not fit
    EXPECT_FALSE(saveHouse(house(60), 0.1, t.path("h"), e));
  }
  EXPECT_NE(e.find("File too large"), std::string::npos) << e;
  EXPECT_EQ(slurp(t.path("h/house.yaml")) + slurp(t.path("h/hall.pgm")), before);
  EXPECT_EQ(entries(t.path()), std::vector<std::string>{"h"}) << "no staging directory left";
}

}  // namespace
}  // namespace nxtmap::network
