// The explorer's safety stop for thinking: ExplorerConfig::maxActions counts what the robot does, not the think
// slices of a travel search, so a strategy that starts search after search without ever acting would spin for
// ever. More than Explorer's limit of searches in a row ends the run (ActionLimit); searches between actions do not.
#include <gtest/gtest.h>

#include <memory>

#include "common/explore/Explorer.hpp"
#include "common/explore/ExplorerStorage.hpp"

namespace nxtmap {
namespace {

// A strategy that searches whenever it is asked to decide, and after each search either searches again or
// turns a quarter (the robot acts).
class Searcher final : public Explorer {
 public:
  Searcher(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config, bool actsBetween)
      : Explorer(map, planner, config), actsBetween_(actsBetween) {}
  const char* name() const override { return "searcher"; }
  int searches = 0;

 protected:
  Action decide() override { return search(); }
  Action searchDone(uint8_t) override { return actsBetween_ ? Action::turn(2) : search(); }

 private:
  Action search() {
    ++searches;
    return startSearch(0);
  }
  bool actsBetween_;
};

struct SearchRun {
  using Storage = ExplorerStorage<16, 16, 64>;
  std::unique_ptr<Storage> storage = std::make_unique<Storage>();
  MapLayers map{storage->map.view(), Storage::kWidth(), Storage::kHeight()};
  TravelPlanner planner{storage->travel.view(), Storage::kWidth(), Storage::kHeight()};
  std::unique_ptr<Searcher> explorer;
  long steps = 0;

  explicit SearchRun(bool actsBetween) {
    ExplorerConfig c;
    c.maxActions = 200;
    explorer = std::make_unique<Searcher>(map, planner, c, actsBetween);
    Action a = explorer->step(Event::startAt(Pose{}));
    while (!explorer->finished() && steps < 1000000) {
      ++steps;
      if (a.kind == Action::Kind::Turn) {
        a = explorer->step(Event::turned(a.amount));
      } else if (a.kind == Action::Kind::Read) {
        RangeReading r;
        r.status = RangeStatus::TooFar;
        r.samples = 1;
        a = explorer->step(Event::range(a.sensor, r));
      } else {
        a = explorer->step(Event::thought());
      }
    }
  }
};

TEST(IdleSearchLimit, AStrategyThatOnlySearchesIsStoppedAfterThirtyThreeSearchesInARow) {
  SearchRun run(false);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_EQ(run.explorer->end(), ExplorerEnd::ActionLimit);
  EXPECT_EQ(run.explorer->searches, 33);
}

TEST(IdleSearchLimit, SearchesBetweenActionsRunOnToTheActionLimit) {
  SearchRun run(true);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_EQ(run.explorer->end(), ExplorerEnd::ActionLimit);
  EXPECT_GT(run.explorer->searches, 150) << "stopped by the actions counted (200), not by the searches";
}

}  // namespace
}  // namespace nxtmap
