#pragma once
#include <cstdint>

#include "common/explore/Counters.hpp"
#include "common/explore/Explorer.hpp"
#include "common/grid/CellSet.hpp"
#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/motion/FaceLines.hpp"
#include "common/motion/PoseTracker.hpp"
#include "common/motion/SideWalls.hpp"
#include "common/motion/StartSquaring.hpp"
#include "common/motion/ThreePointTurn.hpp"
#include "common/motion/TurnCalibration.hpp"

namespace nxtmap {

struct PilotConfig {
  PoseNoise noise{};
  bool correct = true;         // false: plain conversion, no steering and no pose readings
  int32_t readAboveMm = 8;     // read a known wall when the offset along its axis is this uncertain (1 sigma)
  int32_t maxSteerMrad = 150;  // steering towards the next cell's centre is limited to this
  int32_t minRotateMrad = 4;   // smaller corrections are not worth a rotation
  // Steer towards the next cell's centre line only when this far off it (mm): every small rotation
  // costs heading (a turn's error has a floor), while a run on a slightly offset line costs nothing.
  int32_t steerAboveMm = 12;
  int8_t minWallEvidence = 1;  // a wall cell is "known" for pose readings from this evidence up
  // Heading from a straight wall beside the run: two readings of it at least this far apart along
  // the run (mm) measure the heading error; walls are taken as axis-parallel (rectilinear rooms).
  int32_t sideBaseMm = 500;
  int32_t sideReadEveryMm = 500;  // read a wall seen beside the run again after this much driving (0: never)
  int32_t maxSideSlopeMrad = 40;  // a larger apparent slope is another wall (a corner, a doorway)
  // The tracker's gate (PoseNoise::gateMm) is at least this many tenths of a cell (0: gateMm alone): a wall
  // a cell away is still refused, and on the brick's 20 cm cells a robot that drifted 4-6 cm unseen is
  // pulled back (nxt noise, 18 rooms, seeds 1-10 and 11-20 each: 1.3 points more detected and 4 and 2 fewer
  // lost runs than with 40 mm; 10 cm cells keep 40 mm).
  int8_t gateCellTenths = 3;
  // Walls the map already knows are read for the pose up to this range (cm), beyond the range the
  // explorer maps with: an echo from there is never mapped, only matched against a known wall face
  // with free cells before it. 0 or at most the mapping range: the mapping range only.
  int16_t poseRangeCm = 250;
  // The explorer's readings are handed over as if taken from the believed cell's centre (the
  // tracker's offset along the beam added), so an off-centre robot marks its echoes in the right cells.
  bool centreReadings = true;
  // How uncertain the heading is at the start (mrad^2): 0 for a robot put down on the axis; a robot
  // handed over by another pilot starts with that pilot's handOverHeadingVariance().
  int64_t startHeadingVarianceMrad2 = 0;
  // A robot set down off square turns square to the room's walls before the explorer starts
  // (StartSquaring): the half-width of its sweep, mrad (1571: +-90 deg, any angle). 0: it starts as it
  // stands (the published set-up, and every room after the first, entered square through its doorway).
  int16_t squareSweepMrad = 0;
  int16_t squareStepMrad = 87;  // between the sweep's headings
  int16_t sonarConeMrad = 262;  // the sonar's widest beam half-angle (the NXT's 15 deg): how wide a wall's dip is
  // How well the squared heading is known (1 sigma, mrad): the estimate's spread plus the final turn's.
  int16_t squaredHeadingMrad = 20;
  // How well the heading is known when the sweeps saw no straight wall (1 sigma, mrad): set down within 10 deg
  // of square, turned back by the encoders after every sweep and approach. The walls seen while mapping square
  // it then (PoseTracker::measureHeading through the side walls' slopes).
  int16_t unsquaredHeadingMrad = 175;
  // After the sweep (square to the walls, or as set down when it saw no straight wall), the nearest wall no
  // farther than this (cm) across and along lays the cells' edges where its face should lie
  // (RangeGeometry::faceMm): the robot starts off its cell's centre by what that takes (walls in the honest
  // world are not on a cell edge where the robot was set down). An axis left unlaid maps a wall whose face
  // lies within faceMarginCm past an edge a cell too near (one start in five): every good reading lays it, up
  // to the brick's mapping range (RangeGeometry::maxCm, 120 cm).
  int16_t snapRangeCm = 120;
  // A sweep that saw no straight wall (all of them too far, over 160 cm, in the middle of a large room): the
  // robot drives towards an echo of the sweep beyond approachCm + 20 cm until approachCm from it (at most
  // approachMaxCm), turns back to the heading it was set down on and sweeps again, up to approaches times (a
  // sweep beside one wall alone may not place it; a second approach finds a corner). The first approach goes to
  // the nearest echo, later ones to the farthest (StartSquaring::approachEcho: in a cluttered room the nearest
  // echoes are small things; about 40 s a sweep). A sweep with no echo at all drives approachMaxCm blind: ahead
  // of the heading it was set down on, then to its right, by turns. 0: it maps as set down.
#ifndef NXTMAP_NO_START_SQUARING  // (not in the RAM-run image, which has no sweep)
  int16_t approachCm = 50;
  int16_t approachMaxCm = 150;
  uint8_t approaches = 4;
#endif
  // With the sweep on: first measure how far the turns are off (TurnCalibration, this many whole turns
  // between two sweeps; 0: no calibration) and correct every turn by it for the rest of the run.
  uint8_t calibrateTurns = 0;
  // With the sweep on and calibrateTurns 0, a robot that knows its turns no better than an uncalibrated one
  // (WheelCalibration::turnsUnknown: nothing stored, nothing learnt) calibrates with this many turns all the
  // same, once: what it measures is kept. 0: never unasked.
  uint8_t calibrateUnknownTurns = 4;
  // What the wheels' systematic errors are known to be (from a calibration before, a room before; the
  // defaults: an uncalibrated robot's). Every rotation is commanded divided by (1 + turn error) and what the
  // encoders report multiplied by it; the tracker predicts the drift and steering takes it out. Both are
  // learnt further from the walls as the robot goes (PoseTracker), and a turn calibration adds what it measures.
  WheelCalibration wheels{};
  // A quarter turn whose encoders count this much (mrad) short of what was told has stalled (the body met
  // something): the robot turns back by what it turned and the explorer hears that its way is blocked; a
  // levelling rotation that stalls is not tried again until the robot has moved. (Not in the RAM-run
  // image, which has no room for it: there a stalled turn is taken as done, as the encoders counted it.)
  int32_t turnStallMrad = 100;
  // Faces anywhere (RangeGeometry::faceMarginCm > 0): a wall's face is learnt (FaceLines) from readings taken
  // while the offset along the beam, with the reading's own error, is known to this (1 sigma, mm), as well as
  // it is then known; only learnt faces are read for the pose, and a face known less well than the robot's
  // offset learns from the reading instead of correcting the offset.
  int32_t learnFaceBelowMm = 40;
};

// Pilot: between the explorer (cells, quarter turns) and the wheels (mm, mrad). It carries out
// the explorer's actions while keeping the robot on the cell grid: a PoseTracker follows the
// robot's real offset and heading error; every echo from a wall the map already knows (cell faces)
// corrects them; a move that starts off the centre line steers towards the next cell's centre, each turn takes the
// heading error out, and so does a rotation before each of the explorer's readings (a reading
// taken at the steering angle would be marked along the axis, in the wrong cells far out). When the offset grows uncertain it reads a known wall itself (counted as a
// sensor request, like every other reading). Never blocks; the explorer is owned by the caller.
// Limits: the reference is the cell face, so walls off the cell edges bias the offset (up to half
// a cell), and in open space with no known wall in range the heading still drifts.
class Pilot {
 public:
  Pilot(Explorer& explorer, const PilotConfig& config);
  Pilot(const Pilot&) = delete;
  Pilot& operator=(const Pilot&) = delete;

  // Feeds one event (DriveEvent::start() first) and returns what to do next.
  DriveAction step(const DriveEvent& e);
  bool finished() const { return phase_ == Phase::Done; }
  // The explorer has started: the start's sweep (and calibration) is over, or there was none.
  bool explorerStarted() const {
#ifdef NXTMAP_NO_START_SQUARING
    return phase_ != Phase::Idle;  // no sweep there
#else
    return phase_ != Phase::Idle && phase_ != Phase::Square && phase_ != Phase::Approach && phase_ != Phase::Snap;
#endif
  }

  // Cells the caller holds closed without their being walls (a doorway kept shut while a room is
  // mapped): never a landmark for a pose reading. Non-owning: the set must outlive the pilot or be
  // replaced (nullptr: none).
  void setVirtualWalls(const CellSet* cells) { virtual_ = cells; }

  // The rotation that takes the known heading error out (Done when there is none worth a turn):
  // for handing the robot over to another pilot, whose tracker starts exactly on the axis.
  DriveAction levelling() const;
  // The heading's variance (mrad^2) once levelling() is carried out: what the next pilot starts with.
  int64_t handOverHeadingVariance() const;

  // What the start's sweep found (not found when the pilot does not square, see PilotConfig).
#ifndef NXTMAP_NO_START_SQUARING
  const StartSquaring& squaring() const { return squaring_; }
  const TurnCalibration& calibration() const { return calibration_; }
  // The turns' error the pilot corrects by (ppm, see PilotConfig::wheels).
  int32_t turnErrorPpm() const { return turnErrorPpm_; }
  // What the wheels are now believed to do (the turn error corrected by and the drift learnt): for the
  // next run, the next room, the brick's store.
  WheelCalibration wheels() const;
#else
  int32_t turnErrorPpm() const { return 0; }
  WheelCalibration wheels() const { return config_.wheels; }
#endif
  // The explorer's counters plus the pilot's own pose readings and correction rotations.
  Counters counters() const;
  const PoseTracker& tracker() const { return tracker_; }
  const Explorer& explorer() const { return explorer_; }
  uint32_t poseReadings() const { return poseReads_; }

 private:
  enum class Phase : uint8_t {
    Idle,
    Square,
    Approach,
    Snap,
    Level,
    ExplorerRead,
    PoseRead,
    Turn,
    TurnBack,
    Steer,
    Unsteer,     // a steered drive was blocked: back to the heading before the steering, then drive again
    ThreePoint,  // a stalled quarter turn finished by driving out at the angle it got to (ThreePointTurn)
    Drive,
    Think,
    Done
  };

  DriveAction stepCorrected(const DriveEvent& e);  // step() in the robot's true angles
  DriveAction startExplorer(int64_t headingVarianceMrad2);
  DriveAction square(const DriveEvent& e);  // the start's sweep (Phase::Square)
  DriveAction snap(const DriveEvent& e);    // once square, the cell's lattice laid on the nearest walls
  DriveAction approach(const DriveEvent& e);
  // After a sweep that saw no straight wall: Phase::Approach (towards an echo, back, sweep again) when there is
  // one to take (StartSquaring::approachEcho).
  void approachIfFar();
  int approachesLeft() const;  // approaches approachIfFar may still make (PilotConfig::approaches)
  DriveAction begin(const Action& a);
#ifndef NXTMAP_NO_START_SQUARING
  DriveAction turnStalled(const DriveEvent& e);  // Phase::Turn's rotation stalled: a three-point turn, or turn back
  DriveAction threePoint(const DriveEvent& e);   // Phase::ThreePoint's drive or rotation is over
  DriveAction giveUpTurn();  // the quarter turn is given up: turn back by what it turned (ThreePointTurn::partialMrad)
  DriveAction turnedBack(const DriveEvent& e);   // Phase::TurnBack's rotation is over
  void droveTurned(int32_t mm, int32_t offMrad);  // the tracker: a drive at offMrad off the axis heading
  bool levelHeld() const { return levelHeld_; }
#else
  bool levelHeld() const { return false; }
#endif
  DriveAction turnMade(int32_t mrad);  // Phase::Turn's quarter turn is made: turned mrad (encoders)
  DriveAction beginMove();
  DriveAction driveToCentre();
  // The first cell along d that is not free, within the pose range (k cells out): true when it is occupied.
  bool firstWall(Dir d, Cell& wall, int16_t& k) const;
  // The first wall along d is a landmark: its face (mm from the believed centre) and its cell.
  // With faces anywhere only a learnt face is one, and *faceVarianceMm2 (when given) says how well it is known.
  bool knownWall(Dir d, int32_t& faceMm, Cell& wall, int32_t* faceVarianceMm2 = nullptr) const;
  // A good reading along d of the map's first wall there: learn its face, as well as the pose is known.
  void learnFace(Dir d, const RangeReading& r);
  // The wall cell, seen along d, is part of a straight face across the beam: the cells on either
  // side of it are walls too, with free cells before them.
  bool straightFace(Cell wall, Dir d) const;
  bool poseReadWanted(Sensor& s) const;
  void observe(Sensor s, const RangeReading& r);
  RangeReading centred(Sensor s, RangeReading r) const;  // as if read from the believed cell's centre
  void observeSide(Dir d, int32_t rangeMm);
  int16_t wallLine(Dir d, int32_t rangeMm) const;
  bool sideReadWanted(Sensor& s) const;
  bool wallBeside(Dir d) const;  // the map's first non-free cell along d within range is a wall
  void startRun();               // a straight run starts (a quarter turn)

  Explorer& explorer_;
  PilotConfig config_;
  PoseTracker tracker_;
#ifndef NXTMAP_NO_START_SQUARING  // the RAM-run firmware image has no room for the sweep, the
  StartSquaring squaring_;        // calibration and the turn correction (PilotConfig's are ignored there)
  TurnCalibration calibration_;
  int32_t turnErrorPpm_;  // the turn error every rotation is corrected by, ppm (see PilotConfig::wheels)
  FaceLines faces_;       // the learnt faces of the walls read for the pose (faces anywhere only)
  // Phase::Snap: per axis (0 across the start heading's columns, 1 along its rows) the nearest wall's
  // distance from the robot's centre (mm, 0 = none yet) and the offset from the cell centre that puts its
  // face on a cell edge (mm, the tracker's x and y).
  int32_t snapDistMm_[2] = {0, 0};
  int32_t snapMm_[2] = {0, 0};
  // The heading's variance the explorer starts with once the snap is read (mrad^2): the explorer starts on
  // the next Thought, so that its first planning is a slice of its own, not part of the last reading's.
  int64_t snapVarianceMrad2_ = 0;
  // Phase::Approach (see PilotConfig::approachCm): 0 turning towards the echo, 1 driving, 2 turning back; the
  // turn (mrad, as the encoders told it) and the drive (mm).
  uint8_t approachStep_ = 0;
  uint8_t approached_ = 0;  // approaches made
  int32_t approachTurnMrad_ = 0, approachMm_ = 0;
  uint32_t approachCells_ = 0;  // driven, whole cells (for the time counted)
  // The finished sweeps' (and calibration's) readings, raw samples and rotation (mrad), for the counters.
  uint32_t sweepReads_ = 0, sweepSamples_ = 0, sweepMrad_ = 0;
  template <class Sweep>  // StartSquaring or TurnCalibration, just finished
  void countSweep(const Sweep& s) {
    sweepReads_ += s.readings();
    sweepSamples_ += s.samples();
    sweepMrad_ += s.turnedMrad();
  }
#endif
  Pose startPose_{};  // where the explorer starts once the robot is square
  int32_t cellMm_;
  int16_t poseCells_;  // cells out to which known walls are pose landmarks (>= the mapping range's)
  Phase phase_ = Phase::Idle;
  Action pending_;                    // the explorer's action being carried out
  int32_t commandMrad_ = 0;           // rotation in progress
  int32_t driveMm_ = 0;               // drive in progress
  uint8_t readHere_ = 0;              // bit per Dir: read since the robot last moved
  const CellSet* virtual_ = nullptr;  // see setVirtualWalls
  SideWalls sides_;  // the walls read beside the path, for the heading (and the side-reading policy)
  uint32_t poseReads_ = 0, poseSamples_ = 0, correctionMrad_ = 0;
  int64_t turnedUrad_ = 0;     // quarter turns asked by the explorer, microradians
  int64_t commandedUrad_ = 0;  // of them, commanded to the wheels (whole mrad)
#ifndef NXTMAP_NO_START_SQUARING
  int16_t quarterMrad_ = 0;  // the quarter-turn part of the turn in progress (commandMrad_ less the levelling)
  // The steering rotation of the move in progress (mrad, encoders; 0: none, or already taken back). A body that
  // fits a narrow passage square to it may not when turned: a steered drive that is blocked is driven again
  // unsteered before the explorer hears that the way is blocked.
  int16_t steeredMrad_ = 0;
  // A quarter turn that stalled: being finished (Phase::ThreePoint), or given up (Phase::TurnBack, turning back
  // from its partialMrad()).
  ThreePointTurn threePoint_;
  // A levelling rotation stalled (the body touches something): no more levelling until the robot moves.
  bool levelHeld_ = false;
#endif
};

}  // namespace nxtmap
