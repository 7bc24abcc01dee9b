// The explorer's safety stops from outside: a strategy whose decision never ends (it searches, and
// searches again, and never acts) ends the run ActionLimit after Explorer::kMaxThinks think slices in a
// row; one that thinks long and then decides is not stopped.
#include <gtest/gtest.h>

#include "common/explore/Explorer.hpp"
#include "common/explore/TravelPlanner.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

// Searches the room `searches` times (kForever: for ever) before it says it is done.
class Ponderer final : public Explorer {
 public:
  static constexpr int kForever = -1;
  Ponderer(MapLayers& map, TravelPlanner& planner, int searches)
      : Explorer(map, planner, ExplorerConfig{}), searchesLeft_(searches) {}
  const char* name() const override { return "ponderer"; }

 protected:
  Action decide() override {
    if (searchesLeft_ == 0) return Action::done();
    if (searchesLeft_ > 0) --searchesLeft_;
    return startSearch(0);
  }
  bool searchVisit(uint8_t, Cell, uint16_t) override { return false; }  // every reachable cell
  Action searchDone(uint8_t) override { return decide(); }

 private:
  int searchesLeft_;
};

TEST(ExplorerSafetyStop, ADecisionThatNeverEndsEndsTheRunAfterKMaxThinksSlicesInARow) {
  const struct {
    int searches;
    ExplorerEnd end;
  } cases[] = {{Ponderer::kForever, ExplorerEnd::ActionLimit}, {3000, ExplorerEnd::Complete}, {0, ExplorerEnd::Complete}};
  for (const auto& k : cases) {
    test::GridFixture f;
    f.draw({"########", "#......#", "#......#", "#......#", "########"}, 1, 1);  // all known: nothing to read
    TravelStorage<32, 32, 512> storage;
    TravelPlanner planner(storage.view(), 32, 32);
    Ponderer p(f.map, planner, k.searches);
    Action a = p.step(Event::startAt(Pose{Cell{0, 0}, Dir::North}));
    long thinks = 0;
    while (a.kind == Action::Kind::Think && thinks <= 2L * Explorer::kMaxThinks) {
      ++thinks;
      a = p.step(Event::thought());
    }
    const std::string what = "searches " + std::to_string(k.searches) + ", " + std::to_string(thinks) + " thinks";
    EXPECT_EQ(a.kind, Action::Kind::Done) << what;
    ASSERT_TRUE(p.finished()) << what;
    EXPECT_EQ(p.end(), k.end) << what;
    if (k.end == ExplorerEnd::ActionLimit) {
      EXPECT_EQ(thinks, Explorer::kMaxThinks) << what;
    } else if (k.searches > 0) {
      EXPECT_GT(thinks, Explorer::kMaxThinks / 2) << what << ": a long decision, not stopped";
    }
  }
}

}  // namespace
}  // namespace nxtmap
