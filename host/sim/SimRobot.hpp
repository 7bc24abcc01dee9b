// SimRobot: the simulated robot, four ultrasonic sensors and two wheels, moving through a Scene (continuous
// geometry) with a continuous true pose. Its sonar is SonarModel, its drive WheelModel; its body, sensor
// mounts and grid cell come from its RobotDescription. Seeded: the same seed gives the same run.
// Plane: x right, y DOWN, cm; heading in compass degrees clockwise from N (0 = N, 90 = E).
// Cells are those of the robot's grid (GridFrame): cell (col, row) of the frame is cell (col, row) of the
// truth raster the run is scored against.
#pragma once

#include "host/sim/GridFrame.hpp"
#include "host/sim/Heading.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/Scene.hpp"
#include "host/sim/SonarModel.hpp"
#include "host/sim/WheelModel.hpp"
#include "host/sim/World.hpp"

#include <cstdint>
#include <memory>
#include <random>

namespace nxtmap::sim {

struct MoveResult {
  int cellsMoved;  // cells actually stepped, with the sign of the request (-2 = two cells backwards)
  bool blocked;    // true if the body met an obstacle and stopped the move early
};

class SimRobot {
 public:
  static constexpr int kNoEcho = 255;  // raw reading for "no echo"

  // A robot in `scene` on the grid `frame`, its centre at `startCm` facing compass `headingDeg`.
  SimRobot(std::shared_ptr<const Scene> scene, const RobotDescription& robot, const GridFrame& frame,
           const Vec2& startCm, double headingDeg, const NoiseProfile& noise, uint64_t seed, double maxRangeCm = 255.0);
  // A point robot of the world's own cells (the published set-up) in a raster world traced into a scene:
  // starts at the centre of (startCol, startRow) facing heading; sensors mountOffsetCm ahead of the centre.
  SimRobot(const World& world, int startCol, int startRow, Heading heading, const NoiseProfile& noise, uint64_t seed,
           double maxRangeCm = 255.0, double mountOffsetCm = 0.0);

  // One raw ultrasonic sample of sensor 0 front, 1 right, 2 back, 3 left: whole cm 0..254, or 255 = no echo
  // (also for a sensor index outside 0..3). othersFiring: another sensor pings at the same moment.
  int ping(int sensor, bool othersFiring = false);
  // The same at emulated time `atMs` (the emulator's clock): cross-talk follows the real ping times.
  int pingAt(int sensor, double atMs, bool othersFiring = false);
  // Drives |cells| cells forward (cells > 0) or backward (cells < 0) one at a time; stops before an obstacle.
  MoveResult move(int cells);
  // Turns by eighths of a full turn, + = clockwise (2 = 90 degrees right).
  void turn(int eighths);
  // Continuous motion (the emulated brick's wheels): puts the centre at (xCm, yCm) facing headingDeg,
  // unless the body there touches an obstacle; then returns false and the pose is unchanged.
  bool setPose(double xCm, double yCm, double headingDeg);
  // Turns in place by any angle, + = clockwise, through the wheel model. If the body's corners meet an
  // obstacle on the way the wheels stall there: the robot stays turned as far as it got and returns false.
  // (A 16 x 18 cm body sweeps 12 cm from its centre: it cannot spin in a 20 cm cell beside a wall.)
  bool rotate(double deg);
  // How much of the last rotate()/turn() the wheels carried out before a stall, 0..1 (1: all of it): the
  // share of its counts the encoders measured.
  double lastSpinShare() const { return lastSpinShare_; }
  // The last rotate()/turn() as the encoders counted it (deg, + clockwise; WheelStep::countedDeg), the stalled
  // part only when it stalled.
  double lastSpinCountedDeg() const { return lastSpinCountedDeg_; }
  // Drives straight by cm (+ forward, - backward) through the wheel model. If the body would meet an
  // obstacle on the way, the wheels stall and the robot stays where it started: returns false.
  bool drive(double cm);

  double xCm() const { return x_; }
  double yCm() const { return y_; }
  double headingDeg() const { return heading_; }  // 0 <= h < 360
  int col() const;                                // cell of the frame holding the centre
  int row() const;
  Heading nominalHeading() const;  // heading against the frame, rounded to 90 degrees
  double cellCm() const { return frame_.cellCm; }
  const GridFrame& frame() const { return frame_; }
  void setFrame(const GridFrame& frame) { frame_ = frame; }  // the grid col()/row() answer in
  const Scene& scene() const { return *scene_; }
  const RobotDescription& description() const { return robot_; }
  const NoiseProfile& noise() const { return noise_; }
  WheelModel& wheels() { return wheels_; }
  const WheelModel& wheels() const { return wheels_; }
  uint64_t rawPings() const { return rawPings_; }  // ping() calls so far

 private:
  bool fits(double xCm, double yCm, double headingDeg) const;
  bool spin(const WheelStep& step);   // turns the body, stopping where it meets an obstacle
  bool drive(const WheelStep& step);  // drives the wheels' actual motion, all or nothing
  void setHeading(double deg);

  std::shared_ptr<const Scene> scene_;
  RobotDescription robot_;
  GridFrame frame_;
  NoiseProfile noise_;
  std::mt19937_64 rng_;
  SonarModel sonar_;
  WheelModel wheels_;
  double maxRangeCm_;
  double x_;
  double y_;
  double heading_;
  double clockMs_ = 0.0;        // simulated time: pings and motion advance it
  double lastSpinShare_ = 1.0;  // see lastSpinShare()
  double lastSpinCountedDeg_ = 0.0;  // see lastSpinCountedDeg()
  uint64_t rawPings_ = 0;
};

}  // namespace nxtmap::sim
