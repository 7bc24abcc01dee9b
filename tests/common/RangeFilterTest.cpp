#include <gtest/gtest.h>

#include <vector>

#include "common/sensing/RangeFilter.hpp"

namespace nxtmap {
namespace {

struct FilterCase {
  const char* name;
  std::vector<uint8_t> raw;
  RangeStatus status;
  int16_t cm;       // Good: the distance; TooFar: the echo beyond the range, 0 when the samples disagree
  uint8_t samples;  // raw samples consumed
};

// Each case through the filter: its status, samples and range (cm is 0 where there is no range).
void expectFiltered(const RangeGeometry& g, const std::vector<FilterCase>& cases) {
  for (const FilterCase& c : cases) {
    const RangeReading r = RangeFilter::filter(g, c.raw.data(), static_cast<uint8_t>(c.raw.size()));
    EXPECT_EQ(r.status, c.status) << c.name;
    EXPECT_EQ(r.samples, c.samples) << c.name;
    EXPECT_EQ(r.cm, c.cm) << c.name;
  }
}

TEST(RangeFilter, SensorRulesFromTable) {
  const RangeGeometry g{10, 5, 100, 0};
  const std::vector<FilterCase> cases = {
      {"three agreeing echoes stop early", {42, 43, 42, 99, 99}, RangeStatus::Good, 42, 3},
      {"averages accepted samples", {40, 44, 60, 41, 43, 42, 40, 44, 41, 43}, RangeStatus::Good, 42, 10},
      {"no echo", {255, 255, 255}, RangeStatus::NoEcho, 0, 3},
      {"at the minimum is too near", {5, 5, 5}, RangeStatus::TooNear, 0, 3},
      {"below the minimum is too near", {3, 2, 4}, RangeStatus::TooNear, 0, 3},
      {"just above the minimum is good", {6, 6, 6}, RangeStatus::Good, 6, 3},
      {"at the maximum is good", {100, 100, 100}, RangeStatus::Good, 100, 3},
      {"above the maximum is too far", {101, 150, 120}, RangeStatus::TooFar, 0, 3},
      {"no echo and too far mix into too far",
       {255, 150, 255, 130, 255, 255, 140, 200, 180, 255},
       RangeStatus::TooFar,
       0,
       10},
      {"agreeing echoes beyond the range keep their distance", {180, 181, 180}, RangeStatus::TooFar, 180, 3},
      {"a majority of agreeing far echoes among dropouts",
       {180, 255, 181, 179, 180, 180, 255, 182, 180, 181},
       RangeStatus::TooFar,
       180,
       10},
      {"far echoes that agree only in a minority give no distance",
       {180, 255, 181, 255, 180, 255, 255, 182, 150, 255},
       RangeStatus::TooFar,
       0,
       10},
      {"one dropout among echoes", {50, 255, 50, 51, 50, 49, 50, 50, 51, 50}, RangeStatus::Good, 50, 10},
      {"scattered echoes are inconsistent",
       {20, 80, 50, 35, 95, 10, 65, 255, 3, 150},
       RangeStatus::Inconsistent,
       0,
       10},
      {"half rejected is inconsistent",
       {50, 255, 50, 255, 50, 255, 50, 255, 50, 255},
       RangeStatus::Inconsistent,
       0,
       10},
  };
  expectFiltered(g, cases);
}

TEST(RangeFilter, TakesTheSensorsLinearErrorOff) {
  // The brick's geometry with the LEGO sensor's fit, raw = 0.9757 x true + 1.88 cm: readings are true distances,
  // and so are the limits (7 cm, 1.2 m).
  RangeGeometry g{20, 7, 120, 6};
  g.scalePer10k = 9757;
  g.biasMm = 19;
  const std::vector<FilterCase> cases = {
      {"a near wall reads long", {21, 21, 21}, RangeStatus::Good, 20, 3},
      {"a far wall reads short", {100, 100, 100}, RangeStatus::Good, 101, 3},
      {"the samples' mean is corrected, not each sample", {41, 42, 42}, RangeStatus::Good, 41, 3},
      {"raw 9 cm is 7.3 cm: too near", {9, 9, 9}, RangeStatus::TooNear, 0, 3},
      {"raw 10 cm is 8.3 cm: good", {10, 10, 10}, RangeStatus::Good, 8, 3},
      {"raw 119 cm is 120.0 cm: good", {119, 119, 119}, RangeStatus::Good, 120, 3},
      {"raw 120 cm is 121.0 cm: too far", {120, 120, 120}, RangeStatus::TooFar, 121, 3},
      {"an echo beyond the range keeps its true distance", {180, 180, 180}, RangeStatus::TooFar, 183, 3},
      {"the farthest echo stays a byte", {254, 254, 254}, RangeStatus::TooFar, 254, 3},
      {"no echo stays no echo", {255, 255, 255}, RangeStatus::NoEcho, 0, 3},
  };
  expectFiltered(g, cases);
}

TEST(RangeFilter, NeverTakesMoreThanTenSamples) {
  RangeFilter f(RangeGeometry{});
  for (int i = 0; i < 30; ++i) f.add(static_cast<uint8_t>(i % 2 ? 255 : 40));
  EXPECT_TRUE(f.done());
  EXPECT_EQ(f.samples(), RangeFilter::kMaxSamples);
}

TEST(RangeGeometry, CellsFromCentimetres) {
  const RangeGeometry g{10, 5, 100, 0};
  EXPECT_EQ(g.freeCells(), 9);
  EXPECT_EQ(g.hitCells(), 10);
  // The near face of cell k is (k - 1/2) cells away; errors under half a cell keep the cell.
  const struct {
    int16_t cm;
    int16_t cell;
  } table[] = {{5, 1}, {9, 1}, {14, 2}, {15, 2}, {19, 2}, {25, 3}, {95, 10}, {99, 10}};
  for (const auto& t : table) EXPECT_EQ(g.hitCell(t.cm), t.cell) << t.cm << " cm";
  const RangeGeometry nxt{20, 5, 100, 5};  // NXT: 20 cm cells, sensor 5 cm ahead of the centre
  EXPECT_EQ(nxt.hitCell(25), 2);
  EXPECT_EQ(nxt.hitCell(5), 1);
}

}  // namespace
}  // namespace nxtmap
