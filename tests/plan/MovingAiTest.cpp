// astar and jps reproduce the published Moving AI optima (within 1e-3) on a sample of every scenario
// file in worlds/movingai (the first problem of each sampled bucket; `make bench` runs them all).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "host/mapio/MapFiles.hpp"
#include "host/plan/MovingAiScenario.hpp"
#include "host/plan/ScenarioCheck.hpp"

namespace nxtmap::plan {
namespace {

std::string source(const std::string& relative) { return std::string(NXTMAP_SOURCE_DIR) + "/" + relative; }

struct ScenarioFile {
  const char* map;
  int bucketStride;  // every n-th bucket (the sample stays small under the sanitizers)
};

TEST(MovingAi, SampleOfEveryScenarioFileMatchesThePublishedOptimum) {
  const ScenarioFile files[] = {{"worlds/movingai/dao/arena2.map", 3},
                                {"worlds/movingai/maze/maze512-1-0.map", 60},
                                {"worlds/movingai/room/8room_000.map", 10},
                                {"worlds/movingai/random/random512-10-0.map", 8},
                                {"worlds/movingai/street/Berlin_0_512.map", 8}};
  auto astar = makePlanner(Algorithm::AStar);
  auto jps = makePlanner(Algorithm::Jps);
  for (const ScenarioFile& f : files) {
    const mapio::MapLoad map = mapio::loadMap(source(f.map));
    ASSERT_TRUE(map.map) << map.error;
    const ScenarioLoad scen = loadScenario(source(std::string(f.map) + ".scen"));
    ASSERT_TRUE(scen.problems) << scen.error;
    std::vector<ScenarioProblem> sample;
    std::map<int, int> perBucket;
    for (const ScenarioProblem& p : *scen.problems) {
      ASSERT_EQ(p.mapWidth, map.map->width()) << f.map;
      ASSERT_EQ(p.mapHeight, map.map->height()) << f.map;
      if (p.bucket % f.bucketStride == 0 && perBucket[p.bucket]++ < 1) sample.push_back(p);
    }
    ASSERT_GE(sample.size(), 15u) << f.map;
    const Traversability grid(*map.map);
    for (Planner* planner : {astar.get(), jps.get()}) {
      const std::vector<ProblemOutcome> out = runProblems(*planner, grid, sample);
      for (size_t i = 0; i < sample.size(); ++i) {
        EXPECT_TRUE(out[i].matches) << f.map << " " << algorithmName(planner->algorithm()) << " bucket "
                                    << sample[i].bucket << ": length " << out[i].length << ", published "
                                    << sample[i].optimal << " (" << statusName(out[i].status) << ")";
      }
    }
  }
}

TEST(MovingAi, MalformedScenarioFilesAreRejected) {
  const std::string dir = ::testing::TempDir();
  struct Bad {
    const char* text;
    const char* expected;
  };
  const Bad cases[] = {
      {"", "empty file"},
      {"version 2\n", "expected 'version 1'"},
      {"0\ta.map\t4\t4\t0\t0\t1\t1\t1.4\n", "expected 'version 1'"},
      {"version 1\n0\ta.map\t4\t4\t0\t0\t1\t1\n", "expected 9 fields"},
      {"version 1\n0\ta.map\t4\t4\tx\t0\t1\t1\t1.4\n", ":2: bad number"},
      {"version 1\n0\ta.map\t4\t4\t0\t0\t1\t1\t-1\n", "bad number"},
  };
  int n = 0;
  for (const Bad& b : cases) {
    const std::string path = dir + "/bad" + std::to_string(n++) + ".scen";
    FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs(b.text, f);
    std::fclose(f);
    const ScenarioLoad s = loadScenario(path);
    EXPECT_FALSE(s.problems) << b.text;
    EXPECT_NE(s.error.find(b.expected), std::string::npos) << s.error;
  }
  EXPECT_NE(loadScenario(dir + "/absent.scen").error.find("cannot open"), std::string::npos);
  const std::string crlf = dir + "/crlf.scen";
  FILE* f = std::fopen(crlf.c_str(), "wb");
  std::fputs("version 1.0\r\n3\tm.map\t8\t9\t1\t2\t3\t4\t2.82842712\r\n", f);
  std::fclose(f);
  const ScenarioLoad s = loadScenario(crlf);
  ASSERT_TRUE(s.problems) << s.error;
  ASSERT_EQ(s.problems->size(), 1u);
  EXPECT_EQ((*s.problems)[0].bucket, 3);
  EXPECT_EQ((*s.problems)[0].start, (MapCell{1, 2}));
  EXPECT_EQ((*s.problems)[0].goal, (MapCell{3, 4}));
  EXPECT_EQ((*s.problems)[0].mapHeight, 9);
  EXPECT_NEAR((*s.problems)[0].optimal, 2.82842712, 1e-12);
}

}  // namespace
}  // namespace nxtmap::plan
