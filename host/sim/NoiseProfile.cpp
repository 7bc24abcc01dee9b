#include "host/sim/NoiseProfile.hpp"

namespace nxtmap::sim {

namespace {

NoiseProfile makeNone() {
    NoiseProfile p;
    p.name = "none";
    return p;
}

NoiseProfile makeTypical() {
    NoiseProfile p;
    p.name = "typical";
    p.rangeSigmaCm = 1.0;
    p.biasCm = 0.5;
    p.dropoutProb = 0.01;
    p.specularMissProb = 0.02;
    p.specularAngleDeg = 60.0;
    p.crosstalkProb = 0.02;
    p.coneHalfAngleDeg = 5.0;
    p.slipSigma = 0.01;
    p.turnSigmaDeg = 0.5;
    return p;
}

NoiseProfile makeHarsh() {
    NoiseProfile p;
    p.name = "harsh";
    p.rangeSigmaCm = 2.5;
    p.biasCm = 1.5;
    p.dropoutProb = 0.05;
    p.specularMissProb = 0.10;
    p.specularAngleDeg = 45.0;
    p.crosstalkProb = 0.08;
    p.coneHalfAngleDeg = 12.0;
    p.slipSigma = 0.03;
    p.turnSigmaDeg = 2.0;
    return p;
}

}  // namespace

std::optional<NoiseProfile> noiseProfileByName(const std::string& name) {
    if (name == "none") return makeNone();
    if (name == "typical") return makeTypical();
    if (name == "harsh") return makeHarsh();
    return std::nullopt;
}

std::vector<std::string> noiseProfileNames() { return {"none", "typical", "harsh"}; }

}  // namespace nxtmap::sim
