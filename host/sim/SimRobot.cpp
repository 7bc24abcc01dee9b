#include "host/sim/SimRobot.hpp"

#include "host/sim/RayCast.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace nxtmap::sim {

SimRobot::SimRobot(const World& world, int startCol, int startRow, Heading heading, const NoiseProfile& noise,
                   uint64_t seed, double maxRangeCm, double mountOffsetCm)
    : world_(&world),
      noise_(noise),
      rng_(seed),
      maxRangeCm_(maxRangeCm),
      mountOffsetCm_(mountOffsetCm),
      cellCm_(world.resolutionM() * 100.0),
      x_((startCol + 0.5) * cellCm_),
      y_((startRow + 0.5) * cellCm_),
      heading_(headingToDeg(heading)) {}

bool SimRobot::chance(double p) {
    if (p <= 0.0) return false;
    return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p;
}

double SimRobot::gaussian(double sigma) {
    if (sigma <= 0.0) return 0.0;
    return std::normal_distribution<double>(0.0, sigma)(rng_);
}

void SimRobot::setHeading(double deg) {
    double h = std::fmod(deg, 360.0);
    if (h < 0.0) h += 360.0;
    if (h >= 360.0) h = 0.0;
    heading_ = h;
}

int SimRobot::col() const { return static_cast<int>(std::floor(x_ / cellCm_)); }
int SimRobot::row() const { return static_cast<int>(std::floor(y_ / cellCm_)); }

Heading SimRobot::nominalHeading() const {
    const long quarter = std::lround(heading_ / 90.0) % 4;
    return static_cast<Heading>(quarter);
}

int SimRobot::ping(int sensor, bool othersFiring) {
    ++rawPings_;
    if (sensor < 0 || sensor > 3) return kNoEcho;
    if (chance(noise_.dropoutProb)) return kNoEcho;
    if (othersFiring && chance(noise_.crosstalkProb)) {
        // Another sensor's burst arrives first: a plausible short echo.
        return std::uniform_int_distribution<int>(3, 50)(rng_);
    }
    const double axis = heading_ + 90.0 * sensor;
    double ax = 0.0;
    double ay = 0.0;
    directionVector(axis, ax, ay);
    const double sx = x_ + mountOffsetCm_ * ax;
    const double sy = y_ + mountOffsetCm_ * ay;

    RayHit best;
    const double cone = noise_.coneHalfAngleDeg;
    const int rays = cone > 0.0 ? kRaysPerCone : 1;
    for (int i = 0; i < rays; ++i) {
        const double offset = rays == 1 ? 0.0 : cone * (2.0 * i / (rays - 1) - 1.0);
        const RayHit h = castRay(*world_, cellCm_, sx, sy, axis + offset, maxRangeCm_);
        // Off-axis parts of the beam reflect away from faces they meet at a grazing angle (a wall
        // parallel to the beam returns no echo); only the axis ray may still graze, see below.
        if (offset != 0.0 && h.incidenceDeg > noise_.specularAngleDeg) continue;
        if (h.hit && (!best.hit || h.distanceCm < best.distanceCm)) best = h;
    }
    if (!best.hit) return kNoEcho;
    if (best.incidenceDeg > noise_.specularAngleDeg && chance(noise_.specularMissProb)) return kNoEcho;

    const double reading = best.distanceCm + noise_.biasCm + gaussian(noise_.rangeSigmaCm);
    const long cm = std::lround(std::clamp(reading, 0.0, static_cast<double>(kNoEcho)));
    return static_cast<int>(std::min<long>(cm, kNoEcho));
}

MoveResult SimRobot::move(int cells) {
    const int dir = cells >= 0 ? 1 : -1;
    const int steps = std::abs(cells);
    for (int done = 0; done < steps; ++done) {
        const double dist = dir * cellCm_ * (1.0 + gaussian(noise_.slipSigma));
        double dx = 0.0;
        double dy = 0.0;
        directionVector(heading_, dx, dy);
        const double nx = x_ + dist * dx;
        const double ny = y_ + dist * dy;
        const int ncol = static_cast<int>(std::floor(nx / cellCm_));
        const int nrow = static_cast<int>(std::floor(ny / cellCm_));
        if (world_->blocked(ncol, nrow)) {
            // Bumped: the robot settles at the centre of the cell it is still in.
            x_ = (col() + 0.5) * cellCm_;
            y_ = (row() + 0.5) * cellCm_;
            return MoveResult{done * dir, true};
        }
        x_ = nx;
        y_ = ny;
    }
    return MoveResult{steps * dir, false};
}

bool SimRobot::setPose(double xCm, double yCm, double headingDeg) {
    if (world_->blocked(static_cast<int>(std::floor(xCm / cellCm_)), static_cast<int>(std::floor(yCm / cellCm_))))
        return false;
    x_ = xCm;
    y_ = yCm;
    setHeading(headingDeg);
    return true;
}

void SimRobot::rotate(double deg) {
    const double scale = std::max(0.25, std::abs(deg) / 90.0);
    setHeading(heading_ + deg + gaussian(noise_.turnSigmaDeg * scale));
}

bool SimRobot::drive(double cm) {
    const double dist = cm * (1.0 + gaussian(noise_.slipSigma));
    double dx = 0.0;
    double dy = 0.0;
    directionVector(heading_, dx, dy);
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(dist))));  // 1 cm or finer
    for (int i = 1; i <= steps; ++i) {
        const double f = dist * i / steps;
        const int c = static_cast<int>(std::floor((x_ + f * dx) / cellCm_));
        const int r = static_cast<int>(std::floor((y_ + f * dy) / cellCm_));
        if (world_->blocked(c, r)) return false;
    }
    x_ += dist * dx;
    y_ += dist * dy;
    return true;
}

void SimRobot::turn(int eighths) { setHeading(heading_ + 45.0 * eighths + gaussian(noise_.turnSigmaDeg)); }

}  // namespace nxtmap::sim
