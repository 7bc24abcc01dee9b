#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// What a sweep says about the room's walls.
struct WallDirectionEstimate {
  bool found = false;    // a wall was seen (two dips that agree, or one clean dip of loneDipMrad() alone)
  int32_t mrad = 0;      // the walls' normals modulo a quarter turn, mrad from the sweep's zero heading,
                         // + clockwise, in [-kQuarterMrad / 2, kQuarterMrad / 2); 0 when not found
  uint8_t dips = 0;      // wall dips found over the four sensors
  uint8_t agreeing = 0;  // of them, within kAgreeMrad of the estimate
};

// WallDirection: the direction of a room's walls from the four sonars swept on the spot.
//
// A sonar with a cone of half-angle b turned past a straight wall at distance d reads d while the wall's
// normal lies inside its cone and d / cos(x - b) at x off the normal beyond it: a flat dip, symmetric about
// the normal whatever the cone, the range error or the sensor's mount. Each sensor's readings over the
// sweep are searched for such dips; a dip's centre (the heading half way between the two headings where
// its flanks rise through a level just above its floor) is a wall normal as that sensor saw it. The four
// sensors face a quarter turn apart, so modulo a quarter turn every dip names the same direction in a
// rectangular room; the estimate is the mean of the largest group that agrees, at least two dips, or one
// dip alone that looks like nothing but a wall (both flanks rising whole, at least loneDipMrad() wide).
//
// Not a wall: a dip cut off by the sweep's ends, a plateau wider than kMaxDipMrad (a round or open
// space) or narrower than minDipMrad() (a small object, whose nearest point is often its corner), a floor
// nearer than kNearCm (whole-cm readings cannot place it), and a plateau whose flank jumps far above its floor (the edge of an object before a wall);
// readings without an echo end a flank but say nothing else. A flank that turns down again before it has
// risen (a nearer wall past a corner) is cut at three quarters of its rise; under kMinRiseCm it locates nothing. Headings are the sweep's own (odometry),
// whole mrad; readings whole cm. Capacity: kMaxSteps headings of four readings (240 bytes).
class WallDirection {
 public:
  static constexpr int kMaxSteps = 40;
  static constexpr int kMaxDips = 16;
  static constexpr int32_t kQuarterMrad = 1571;     // a quarter turn
  static constexpr int32_t kAgreeMrad = 70;         // dips this close (4 deg) name the same walls
  static constexpr int32_t kMaxDipMrad = 1745;      // 100 deg: a wider plateau is no straight wall
  // How wide a dip must be, from the sonar's widest beam half-angle b: an object's nearest point stays in the
  // beam for about 2b and is gone, a wall's flanks rise slowly past it (10 % at 25 deg more). In the brick rooms
  // under nxt (b = 15 deg), dips 30-40 deg wide were 5 deg or more off the walls three times in four, 46-52 deg
  // once in five, 52-69 deg once in twenty: a dip is one from 2b + 10 deg (never under 30), names the walls alone
  // from 2b + 21.5 deg (never under 45), and as the last resort (widestWall) from 2b + 15 deg (never under 45).
  static constexpr int32_t kMinDipMrad = 524;         // 30 deg: the floor of minDipMrad()
  static constexpr int32_t kLoneDipMrad = 785;        // 45 deg: the floor of loneDipMrad() and lastResortDipMrad()
  static constexpr int32_t kNxtConeMrad = 262;        // 15 deg: the NXT sensor's widest beam (the default)
  explicit WallDirection(int32_t coneHalfMrad = kNxtConeMrad);
  int32_t minDipMrad() const { return minDipMrad_; }
  int32_t loneDipMrad() const { return loneDipMrad_; }
  int32_t lastResortDipMrad() const { return lastResortDipMrad_; }
  static constexpr int16_t kNearCm = 20;            // a nearer floor: 1 cm is too much of the range to locate it
  static constexpr int32_t kMaxHeadingMrad = 8000;  // a sweep's headings lie within +-8 rad
  static constexpr int16_t kFarCm = 160;            // farther readings are too coarse for a dip
  static constexpr int16_t kMinRiseCm = 2;          // flanks that rise less locate nothing
  static constexpr int16_t kLoneDropCm = 3;         // a lone reading this far (+ 10 %) below both neighbours is wild
  static constexpr int16_t kCornerDropCm = 4;       // a flank falling this far below its top has passed a corner

  void clear() { steps_ = 0; }
  // Starts the next heading of the sweep (mrad from its zero, + clockwise, increasing, within
  // +-kMaxHeadingMrad). False when full, not increasing or out of range: the heading and its readings
  // are ignored.
  bool addHeading(int32_t mrad);
  // The reading of `s` at the current heading, cm; 0 (or anything outside 1..kFarCm): no usable echo. A reading
  // between two echoes that lies more than kLoneDropCm + 10 % below the nearer of them is taken as that one:
  // the NXT sensor's lone wild echoes ("12 cm when really 30", docs/nxt-sonar-and-odometry.md) would otherwise
  // cut a wall's flank or make a dip of their own.
  void addReading(Sensor s, int16_t cm);
  int steps() const { return steps_; }

  WallDirectionEstimate estimate() const;
  // The last resort when estimate() found nothing and nothing better will be tried (StartSquaring: no approach
  // left): the widest dip that alone looks like nothing but a wall (clean, at least lastResortDipMrad() wide), whatever
  // other dips say. Two walls' dips disagree beyond kAgreeMrad in about one sweep in five (each is off by about
  // 2.4 degrees, 1 sigma); either is nearer the walls than a start heading up to 10 degrees off square.
  WallDirectionEstimate widestWall() const;

  // A dip's centre and width (mrad, sweep headings) by sensor, for tables: fills at most `max`, returns
  // how many were found.
  struct Dip {
    Sensor sensor = Sensor::Front;
    int32_t centreMrad = 0;
    int32_t widthMrad = 0;
    int16_t floorCm = 0;
    bool clean = false;  // both flanks rose through the full level (no corner cut either)
  };
  int dips(Dip* out, int max) const;

 private:
  bool valid(int s, int k) const { return cm_[k][s] > 0 && cm_[k][s] <= kFarCm; }
  bool localMinimum(int s, int k) const;
  // Keeps the first of the dips that lie on the same bearing (two sensors that faced the same wall or
  // object in turn): one feature, one vote. Returns how many are kept, moved to the front.
  static int distinct(Dip* found, int n);
  // The flank of the dip whose floor is at index k, going `dir` (-1, +1): it rises through floor +
  // tolerance, or turns down before at a corner (its highest reading), or is not a wall's (runs off the
  // sweep or jumps).
  struct Flank {
    bool ok = false;
    bool corner = false;
    int16_t topCm = 0;  // ok: floor + tolerance, or the corner's reading
  };
  Flank flankTop(int s, int k, int dir) const;
  // Where that flank passes `level` (mrad), and the last index at or below it.
  int32_t crossing(int s, int k, int dir, int16_t level, int& lastInside) const;

  int16_t minDipMrad_, loneDipMrad_, lastResortDipMrad_;  // mrad (WallDirection(coneHalfMrad))
  int16_t heading_[kMaxSteps] = {};           // mrad, |.| <= kMaxHeadingMrad
  uint8_t cm_[kMaxSteps][kSensorCount] = {};  // whole cm, 0: no usable echo
  int steps_ = 0;
};

}  // namespace nxtmap
