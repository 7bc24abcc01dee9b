#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/RoomGrid.hpp"
#include "common/sensing/BeamModel.hpp"

namespace nxtmap {

struct GridLocaliserParams {
  int16_t cellMm = 200;             // the map's cell edge, mm; a multiple of binMm (20 cm on the brick)
  int16_t binMm = 50;               // a position bin's edge, mm, >= 1
  int16_t headingStepMrad = 35;     // a heading bin, mrad (2 deg), >= 1
  int16_t mountMm = 60;             // a sensor's face ahead of the robot's centre, mm (RangeGeometry::mountCm)
  int16_t slipPerMille = 20;        // along-track error per mm driven, 1 sigma, per mille
  int16_t driveMradPerCell = 3;     // heading error picked up per cell driven, 1 sigma, mrad
  int16_t turnMradPerQuarter = 12;  // heading error of a quarter turn, 1 sigma, mrad (smaller turns: floor 1/4)
  uint8_t rebaseMargin = 16;        // cost (1/8 nat) by which the believed cell must lose to the peak's: 2 nat
};

// GridLocaliser: a histogram (Markov) filter over a small window around the pose the explorer believes in, in
// the conventions of PoseTracker: x east, y north, mm, from the believed cell's centre; theta the actual heading
// minus the believed axis heading, mrad, + clockwise (small: sin t = t, cos t = 1).
//
// Bins: kSide x kSide positions binMm apart centred on the believed cell's centre (+-kRadius bins, +-2.5 cells of
// 20 cm with 5 cm bins) times kHeadings headings headingStepMrad apart centred on the axis. Each holds a cost
// (-ln of its unnormalised probability, 1/8 nat, BeamModel's unit) in one byte, saturating at kFar; the most
// likely bin costs 0 after reset, motion and recentre, and at most kSlack after a reading (the window is
// renormalised when the bin that was the peak at the last normalisation passes kSlack). Storage: kHeadings + 1 layers
// of kSide^2 bytes, each padded to whole words (kBins bytes in all) plus a few words, owned by the object.
//
// Motion: each heading moves its bins along its own actual direction (whole bins, the rest carried per heading),
// so heading error becomes sideways drift; the wheels' noise accumulates as variance and is spread, once it
// reaches a quarter of a bin squared, by a min-convolution with a quadratic kernel (the log-domain gaussian
// blur: variances add). Bins shifted in from outside the window start at kFar.
//
// Measurement: a reading from Sensor s while facing Dir h against a read-only RoomGrid around the believed cell.
// The expected range of each position bin is the distance from its sensor face (mountMm out along the sensor's
// axis; the heading's sideways shift of the face, under 3 mm, is ignored) to the near face of the first occupied
// cell along the row (or column) the face lies in. An unknown cell before any wall: the wall may be anywhere
// beyond its near face, or nowhere in reach, so the bin takes the reading's best explanation that the free cells
// before it allow (no cost for an echo from beyond that face; an echo from inside the free cells costs as one
// from a wall at the face). Not "no information": bins looking into the unknown would otherwise win over every
// bin that sees a wall it fits less than perfectly. A bin's cost grows by the reading's cost under BeamModel
// minus the reading's best possible cost, and the least of the reading's costs over the window is taken off. The first wall is found once per (row, start cell) by one walk per row; costs are looked up
// once per distinct expected range; a reading's costs, the same for every heading, go into one layer kept for the
// readings (one saturating addition per position, four to a word), folded into the heading layers before motion.
// Host-measured (callgrind, x86-64 -O2): about 21,000 instructions a reading, 35,000 when it renormalises.
class GridLocaliser {
 public:
  static constexpr int kRadius = 10;
  static constexpr int kSide = 2 * kRadius + 1;
  static constexpr int kHeadingRadius = 2;
  static constexpr int kHeadings = 2 * kHeadingRadius + 1;
  static constexpr int kLayerWords = (kSide * kSide + 3) / 4;
  static constexpr int kBins = kLayerWords * 4 * (kHeadings + 1);
  static constexpr uint8_t kSlack = 32;  // 4 nat
  static constexpr uint8_t kFar = 255;
  static constexpr int16_t kMaxReachCm = 300;  // BeamParams::limitCm at most (the per-reading cost cache)
  static constexpr int32_t kQuarterMrad = 1571;

  explicit GridLocaliser(const GridLocaliserParams& params = GridLocaliserParams{},
                         const BeamParams& beam = BeamParams{});

  // Centred on the believed pose with gaussian spreads sigmaMm (per axis) and sigmaMrad; 0: exactly there.
  void reset(int32_t sigmaMm = 0, int32_t sigmaMrad = 0);

  // The robot drove `mm` (signed, + forward) believing it faced `heading`.
  void drove(int32_t mm, Dir heading);
  // The robot turned on the spot by `mrad` (+ clockwise) while the believed heading changed by `quarters`.
  void rotated(int32_t mrad, int quarters);
  // The explorer now believes it is `cells` further along `d`: the window follows (cellMm / binMm bins a cell).
  void recentre(Dir d, int cells);

  // A reading (whole cm 0..254, or BeamModel::kNoEcho) from `s` facing `facing`, standing in `believed` of
  // `map`. Returns how many position bins it weighed (every one; 0 for a reading the model cannot weigh).
  int measure(const RoomGrid& map, Cell believed, Dir facing, Sensor s, int16_t readingCm);

  struct Peak {
    int32_t xMm = 0, yMm = 0, thetaMrad = 0;
  };
  // The most likely bin (ties: the one nearest the centre).
  Peak peak() const;
  // The peak lies confidently in another cell: strictly inside it (not on a face) and every bin of the believed
  // cell (faces included) costs rebaseMargin more. dx, dy: the cell the explorer must move its belief to.
  struct Rebase {
    bool needed = false;
    int16_t dxCells = 0, dyCells = 0;
  };
  Rebase rebase() const;
  // Root mean square distance (mm) of the position belief from its mean.
  int32_t spreadMm() const;

  // The cost of bin (x, y, heading) in bins from the centre (|x|, |y| <= kRadius, |heading| <= kHeadingRadius).
  uint8_t at(int x, int y, int heading) const {
    return cost(heading + kHeadingRadius, (y + kRadius) * kSide + x + kRadius);
  }
  const GridLocaliserParams& params() const { return params_; }

 private:
  int32_t binCentreMm(int i) const { return (i - kRadius) * params_.binMm; }
  // Heading layer h as bytes, [y * kSide + x] (the words seen as bytes: unsigned char may alias anything).
  uint8_t* layer(int h) { return reinterpret_cast<uint8_t*>(words_[h]); }
  const uint8_t* layer(int h) const { return reinterpret_cast<const uint8_t*>(words_[h]); }
  uint8_t& bin(int h, int y, int x) { return layer(h)[y * kSide + x]; }
  uint8_t bin(int h, int y, int x) const { return layer(h)[y * kSide + x]; }
  // A bin's cost: its heading layer's plus the readings' since the last fold (saturating).
  uint8_t cost(int h, int i) const {
    const int c = layer(h)[i] + reinterpret_cast<const uint8_t*>(readings_)[i];
    return static_cast<uint8_t>(c > kFar ? kFar : c);
  }
  void fold();  // the readings' layer into every heading's (before motion touches the layers)
  void shiftLayer(int h, int sx, int sy);
  void shiftHeadings(int sh);
  void spreadAlong(int axis);  // 0: x, 1: y, 2: heading; spends the variance accumulated on it
  void normalise();
  void lower(uint8_t by);  // every cost less `by`, at most the lowest

  // The costs, four bins a word (the last word's spare bytes unused): one layer per heading, and the readings' costs
  // since the last motion, the same for every heading and so kept once (a reading adds to one layer, not five).
  uint32_t words_[kHeadings][kLayerWords] = {};
  uint32_t readings_[kLayerWords] = {};
  int watchHeading_ = 0, watchIndex_ = 0;  // the peak at the last normalisation: layer, y * kSide + x
  int32_t carryMm_[kHeadings][2] = {};     // motion not yet shifted, per heading, x and y, |.| <= binMm / 2
  int32_t carryMrad_ = 0;                  // turn not yet shifted, |.| <= headingStepMrad / 2
  int64_t varianceMm2_[2] = {};            // motion variance not yet spread, x and y
  int64_t varianceMrad2_ = 0;
  GridLocaliserParams params_;
  BeamModel model_;
};

static_assert(GridLocaliser::kBins <= 2816, "the histogram's budget: 2-3 KiB");
static_assert(sizeof(GridLocaliser) <= 3072, "the localiser's RAM budget");

}  // namespace nxtmap
