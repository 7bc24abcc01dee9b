#include "host/sim/SonarModel.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Salts: one independent per-pose value per purpose.
enum Salt : uint64_t { kSaltError = 1, kSaltEcho = 2, kSaltLoss = 3, kSaltPhantom = 4 };

uint64_t mix(uint64_t x) {  // splitmix64's finaliser
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

uint64_t hashOf(uint64_t key, uint64_t salt, int ray) {
  return mix(mix(key ^ (salt * 0xd6e8feb86659fd93ULL)) ^ static_cast<uint64_t>(ray + 1));
}

// Uniform in (0, 1) from a hash.
double unitOf(uint64_t h) { return (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53; }

double normalOf(uint64_t key, uint64_t salt) {  // Box-Muller over two hashed uniforms
  const double u1 = unitOf(hashOf(key, salt, 0));
  const double u2 = unitOf(hashOf(key, salt, 1));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

bool chance(double p, std::mt19937_64& rng) {
  if (p <= 0.0) return false;
  return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < p;
}

double gaussian(double sigma, std::mt19937_64& rng) {
  if (sigma <= 0.0) return 0.0;
  return std::normal_distribution<double>(0.0, sigma)(rng);
}

Vec2 unitOfCompass(double deg) {
  const double rad = deg * kPi / 180.0;
  return Vec2(std::sin(rad), -std::cos(rad));
}

double compassOf(const Vec2& v) { return std::atan2(v.x(), -v.y()) * 180.0 / kPi; }

double lerp(double a, double b, double t) { return a + (b - a) * std::clamp(t, 0.0, 1.0); }

}  // namespace

SonarModel::SonarModel(const SonarNoise& noise, double reachCm, uint64_t seed)
    : noise_(noise), reachCm_(reachCm), seed_(seed) {}

double SonarModel::beamHalfAngleDeg(double rangeCm) const {
  const SonarNoise& n = noise_;
  if (n.coneWideDeg <= 0.0) return n.coneHalfAngleDeg;
  if (rangeCm <= n.coneWideAtCm) {
    return n.coneWideAtCm > 0.0 ? lerp(n.coneHalfAngleDeg, n.coneWideDeg, rangeCm / n.coneWideAtCm) : n.coneWideDeg;
  }
  const double span = reachCm_ - n.coneWideAtCm;
  return span > 0.0 ? lerp(n.coneWideDeg, n.coneFarDeg, (rangeCm - n.coneWideAtCm) / span) : n.coneFarDeg;
}

SonarModel::PoseKey SonarModel::keyOf(const Vec2& face, double axisDeg, int sensor) const {
  double axis = std::fmod(axisDeg, 360.0);
  if (axis < 0.0) axis += 360.0;
  const auto qx = static_cast<int64_t>(std::llround(face.x()));
  const auto qy = static_cast<int64_t>(std::llround(face.y()));
  const auto qa = static_cast<int64_t>(std::llround(axis)) % 360;
  uint64_t h = mix(seed_);
  h = mix(h ^ static_cast<uint64_t>(qx));
  h = mix(h ^ static_cast<uint64_t>(qy));
  h = mix(h ^ static_cast<uint64_t>(qa));
  h = mix(h ^ static_cast<uint64_t>(sensor));
  return PoseKey{h};
}

double SonarModel::poseError(const Echo& echo, int sensor, const PoseKey& key, std::mt19937_64& rng) const {
  const double sigma = noise_.poseErrorSigmaCm;
  switch (noise_.poseErrorDraw) {
    case PoseErrorDraw::PerPing: return gaussian(sigma, rng);
    case PoseErrorDraw::PerGeometry: {
      uint64_t h = mix(seed_ ^ 0x5bd1e995ULL);
      h = mix(h ^ static_cast<uint64_t>(std::llround(echo.valueCm)));
      h = mix(h ^ static_cast<uint64_t>(std::llround(echo.incidenceDeg)));
      h = mix(h ^ static_cast<uint64_t>(sensor));
      return sigma * normalOf(h, kSaltError);
    }
    case PoseErrorDraw::PerPose: break;
  }
  return sigma * normalOf(key.hash, kSaltError);
}

bool SonarModel::heardOthers(int sensor, double atMs, bool othersFiring) {
  bool heard = othersFiring;
  for (int k = 0; k < kSensors; ++k) {
    const auto i = static_cast<size_t>(k);
    if (k == sensor || !pinged_[i]) continue;
    const double since = atMs - lastPingMs_[i];
    if (since >= 0.0 && since < noise_.crosstalkWindowMs) heard = true;
  }
  const auto s = static_cast<size_t>(sensor);
  lastPingMs_[s] = atMs;
  pinged_[s] = true;
  return heard;
}

int SonarModel::ping(const Scene& scene, const Vec2& face, double axisDeg, int sensor, double atMs, bool othersFiring,
                     std::mt19937_64& rng) {
  if (sensor < 0 || sensor >= kSensors) return kNoEcho;
  const bool heard = heardOthers(sensor, atMs, othersFiring);
  if (chance(noise_.dropoutProb, rng)) return kNoEcho;
  if (heard && chance(noise_.crosstalkProb, rng)) {
    // Another sensor's burst arrives first: a plausible short echo.
    return std::uniform_int_distribution<int>(3, 50)(rng);
  }
  const PoseKey key = keyOf(face, axisDeg, sensor);
  const Echo best = firstEcho(scene, face, axisDeg, key);
  if (!best.found) return kNoEcho;
  if (best.incidenceDeg > noise_.specularAngleDeg && chance(noise_.specularMissProb, rng)) return kNoEcho;

  double reading = best.valueCm;
  if (noise_.poseErrorSigmaCm > 0.0) reading += poseError(best, sensor, key, rng);
  if (noise_.pingJitterCm > 0.0) {
    reading += std::uniform_real_distribution<double>(-noise_.pingJitterCm, noise_.pingJitterCm)(rng);
  }
  reading += gaussian(noise_.rangeSigmaCm, rng);
  const long cm = std::lround(std::clamp(reading, 0.0, static_cast<double>(kNoEcho)));
  const int raw = static_cast<int>(std::min<long>(cm, kNoEcho));
  return chance(noise_.wildProb, rng) ? wild(raw, rng) : raw;
}

// The first echo to return over the cone's rays (nearest path wins; the first of equal ones).
SonarModel::Echo SonarModel::firstEcho(const Scene& scene, const Vec2& face, double axisDeg, const PoseKey& key) const {
  const SonarNoise& n = noise_;
  const double spread =
      n.coneWideDeg > 0.0 ? std::max({n.coneHalfAngleDeg, n.coneWideDeg, n.coneFarDeg}) : n.coneHalfAngleDeg;
  const int rays = spread > 0.0 ? kRaysPerCone : 1;
  Echo best;
  for (int i = 0; i < rays; ++i) {
    const double offset = rays == 1 ? 0.0 : spread * (2.0 * i / (rays - 1) - 1.0);
    const double rayDeg = axisDeg + offset;
    const SceneHit h = scene.cast(face, rayDeg, reachCm_);
    // Off-axis parts of the beam reflect away from faces they meet at a grazing angle (a wall
    // parallel to the beam returns no echo); only the axis ray may still graze (specularMissProb).
    if (offset != 0.0 && h.incidenceDeg > n.specularAngleDeg) continue;
    if (!h.hit || std::fabs(offset) > beamHalfAngleDeg(h.distanceCm) + 1e-9) continue;
    const Echo e = echoOf(scene, face, axisDeg, rayDeg, h, key);
    if (e.found && (!best.found || e.pathCm < best.pathCm)) best = e;
  }
  return best;
}

// What one ray's hit returns to the sensor, if anything. The per-pose chances are shared by the beam's rays
// (one echo strength per pose): a leg or a far wall is seen by the whole beam or not at all.
SonarModel::Echo SonarModel::echoOf(const Scene& scene, const Vec2& face, double axisDeg, double rayDeg,
                                    const SceneHit& hit, const PoseKey& key) const {
  const SonarNoise& n = noise_;
  const double d = hit.distanceCm;
  Echo e{true, d, linear(d), hit.incidenceDeg};
  if (n.nearFieldCm > 0.0 && d < n.nearFieldCm) {
    if (n.nearFieldMode == NearField::NoEcho || d < kNearFieldBlindCm) return Echo{};
    e.valueCm = d + n.nearFieldHighCm;
  }
  const double pEcho = echoProbability(hit);
  if (pEcho < 1.0 && unitOf(hashOf(key.hash, kSaltEcho, 0)) >= pEcho) return Echo{};
  if (hit.surface == Surface::Hard && n.incidenceLossStartDeg > 0.0) {
    // The sensor turned this far from the face's normal (the angle measured against a flat wall).
    const double cosAxis = std::fabs(unitOfCompass(axisDeg).dot(hit.normal));
    const double turnedDeg = std::acos(std::min(1.0, cosAxis)) * 180.0 / kPi;
    const double width = std::max(1e-9, n.incidenceLossFullDeg - n.incidenceLossStartDeg);
    const double pLoss = n.incidenceLossMaxProb * std::clamp((turnedDeg - n.incidenceLossStartDeg) / width, 0.0, 1.0);
    if (pLoss > 0.0 && unitOf(hashOf(key.hash, kSaltLoss, 0)) < pLoss) {
      const bool bounces = unitOf(hashOf(key.hash, kSaltPhantom, 0)) < n.phantomProb;
      return bounces ? phantom(scene, face, rayDeg, hit) : Echo{};
    }
  }
  return e;
}

// Probability that the surface echoes at this range: the surface's own strength times the range limit
// (a hard wall reliable to reliableRangeCm, never past rangeLimitCm; soft and thin ones scaled down).
double SonarModel::echoProbability(const SceneHit& hit) const {
  const SonarNoise& n = noise_;
  double p = 1.0;
  double factor = 1.0;
  if (hit.surface == Surface::Soft) {
    p = n.softEchoProb;
    factor = n.softRangeFactor;
  } else if (hit.surface == Surface::Thin) {
    p = n.thinEchoProb;
    factor = n.thinRangeFactor;
  }
  if (n.reliableRangeCm > 0.0) {
    const double reliable = n.reliableRangeCm * factor;
    const double limit = std::max(n.rangeLimitCm, n.reliableRangeCm) * factor;
    if (hit.distanceCm > reliable) {
      p *= limit > reliable ? std::clamp((limit - hit.distanceCm) / (limit - reliable), 0.0, 1.0) : 0.0;
    }
  }
  return p;
}

// The sound mirrored off the hard face, met again and returned along the same way: reads the whole path.
SonarModel::Echo SonarModel::phantom(const Scene& scene, const Vec2& face, double rayDeg, const SceneHit& hit) const {
  const Vec2 dir = unitOfCompass(rayDeg);
  const Vec2 mirrored = dir - 2.0 * dir.dot(hit.normal) * hit.normal;
  const Vec2 from = face + dir * hit.distanceCm + hit.normal * 0.01;  // just off the face, on the free side
  const double left = reachCm_ - hit.distanceCm;
  if (left <= 0.0) return Echo{};
  const SceneHit second = scene.cast(from, compassOf(mirrored), left);
  if (!second.hit) return Echo{};
  const double path = hit.distanceCm + second.distanceCm;
  return Echo{true, path, linear(path), hit.incidenceDeg};
}

double SonarModel::linear(double pathCm) const { return noise_.rangeScale * pathCm + noise_.biasCm; }

// An erroneous reading (FTC forum thread 5065): 0, 255, or shorter than the truth, a third each.
int SonarModel::wild(int reading, std::mt19937_64& rng) const {
  const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
  if (kind == 0) return 0;
  if (kind == 1) return kNoEcho;
  return std::uniform_int_distribution<int>(1, std::max(1, std::min(reading, kNoEcho) - 1))(rng);
}

}  // namespace nxtmap::sim
