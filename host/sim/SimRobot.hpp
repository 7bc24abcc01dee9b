// SimRobot: the simulated one-cell robot, four ultrasonic sensors (front, right, back, left) and two wheels,
// moving through a World with a continuous true pose. Seeded: the same seed gives the same run.
// Plane: x = col * cellCm (right), y = row * cellCm (DOWN); heading in degrees clockwise from N (0 = N, 90 = E).
#pragma once

#include "host/sim/Heading.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/World.hpp"

#include <cstdint>
#include <random>

namespace nxtmap::sim {

struct MoveResult {
    int cellsMoved;  // cells actually stepped, with the sign of the request (-2 = two cells backwards)
    bool blocked;    // true if a blocked cell stopped the move early
};

class SimRobot {
public:
    static constexpr int kNoEcho = 255;  // raw reading for "no echo"
    static constexpr int kRaysPerCone = 9;  // rays cast across a beam cone wider than 0

    // The world must outlive the robot. Starts at the centre of (startCol, startRow), facing heading.
    // maxRangeCm: farthest echo, cm; mountOffsetCm: sensor distance from the robot's centre along its axis, cm.
    SimRobot(const World& world, int startCol, int startRow, Heading heading, const NoiseProfile& noise,
             uint64_t seed, double maxRangeCm = 255.0, double mountOffsetCm = 0.0);

    // One raw ultrasonic sample of sensor 0 front, 1 right, 2 back, 3 left: whole cm 0..254, or 255 = no echo
    // (also for a sensor index outside 0..3). othersFiring: other sensors ping at the same time (cross-talk).
    int ping(int sensor, bool othersFiring = false);
    // Drives |cells| cells forward (cells > 0) or backward (cells < 0) one at a time; stops before a blocked cell.
    MoveResult move(int cells);
    // Turns by eighths of a full turn, + = clockwise (2 = 90 degrees right).
    void turn(int eighths);
    // Continuous motion (the emulated brick's wheels): puts the centre at (xCm, yCm) facing headingDeg,
    // unless that point lies in a blocked cell; then returns false and the pose is unchanged.
    bool setPose(double xCm, double yCm, double headingDeg);
    // Turns in place by any angle, + = clockwise. The error grows with the angle: turnSigmaDeg per
    // 90 degrees, with a floor of a quarter of it for small corrections (backlash, wheel scrub).
    void rotate(double deg);
    // Drives straight by cm (+ forward, - backward) with slip. If the centre would enter a blocked
    // cell on the way, the wheels stall and the robot backs off to where it started: returns false.
    bool drive(double cm);

    double xCm() const { return x_; }
    double yCm() const { return y_; }
    double headingDeg() const { return heading_; }  // 0 <= h < 360
    int col() const;                                // cell containing the centre
    int row() const;
    Heading nominalHeading() const;                 // heading rounded to the nearest 90 degrees
    double cellCm() const { return cellCm_; }
    const NoiseProfile& noise() const { return noise_; }
    uint64_t rawPings() const { return rawPings_; }  // ping() calls so far

private:
    bool chance(double p);
    double gaussian(double sigma);
    void setHeading(double deg);

    const World* world_;
    NoiseProfile noise_;
    std::mt19937_64 rng_;
    double maxRangeCm_;
    double mountOffsetCm_;
    double cellCm_;
    double x_;
    double y_;
    double heading_;
    uint64_t rawPings_ = 0;
};

}  // namespace nxtmap::sim
