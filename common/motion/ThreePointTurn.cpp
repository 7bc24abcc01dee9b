#include "common/motion/ThreePointTurn.hpp"

#include "common/math/IntAbs.hpp"
#include "common/math/IntTrig.hpp"

namespace nxtmap {

int32_t ThreePointTurn::outMm(int32_t stalledMrad) {
  const int32_t a = abs32(stalledMrad);
  if (a < kMinStalledMrad || a > kMaxStalledMrad) return 0;
  // The corners' reach across the axis heading: now l cos a + w sin a, at most the half diagonal. The drive out
  // moves the centre sideways by its length times sin a.
  const int32_t now = (kHalfLengthMm * cosPerMille(a) + kHalfWidthMm * sinPerMille(a)) / 1000;
  const int32_t mm = (kReachMm - now + kMarginMm) * 1000 / sinPerMille(a);
  return mm > kMaxOutMm ? kMaxOutMm : (mm < kMarginMm ? kMarginMm : mm);
}

DriveAction ThreePointTurn::begin(int32_t stalledMrad, int32_t restMrad, int direction, int32_t offsetMm) {
  partialMrad_ = static_cast<int16_t>(stalledMrad);
  restMrad_ = static_cast<int16_t>(restMrad);
  stage_ = Stage::GivenUp;
  int32_t mm = outMm(stalledMrad);
  const int32_t cosA = cosPerMille(stalledMrad);  // > 0 when mm > 0 (stalled before kMaxStalledMrad)
  const int32_t roomMm = kMaxOffsetMm - (direction < 0 ? -offsetMm : offsetMm);  // along the heading
  if (mm * cosA > roomMm * 1000) mm = roomMm * 1000 / cosA;
  if (mm < kMarginMm) return DriveAction::done();
  stage_ = Stage::Out;
  outDoneMm_ = static_cast<int16_t>(direction < 0 ? -mm : mm);
  return DriveAction::drive(outDoneMm_);
}

DriveAction ThreePointTurn::step(const DriveEvent& e, int32_t stallMrad, int32_t& droveMm) {
  droveMm = 0;
  const int32_t got = e.measured ? e.achieved : restMrad_;  // a rotation's (a drive's own below)
  switch (stage_) {
    case Stage::Out:  // driven out, or blocked where it stood
      if (e.blocked) break;
      if (e.measured) outDoneMm_ = static_cast<int16_t>(e.achieved);
      droveMm = outDoneMm_;
      stage_ = Stage::Rest;
      return DriveAction::rotate(restMrad_);
    case Stage::Rest:
      partialMrad_ = static_cast<int16_t>(partialMrad_ + got);
      if (abs32(restMrad_ - got) <= stallMrad) {
        stage_ = Stage::Made;
        return DriveAction::done();
      }
      restMrad_ = static_cast<int16_t>(-got);  // stalled again: back to the heading the drive out was made at
      stage_ = Stage::Back;
      return DriveAction::rotate(restMrad_);
    case Stage::Back:
      partialMrad_ = static_cast<int16_t>(partialMrad_ + got);
      stage_ = Stage::In;
      return DriveAction::drive(-outDoneMm_);
    case Stage::In:  // driven back in (or blocked: still out, as the tracker has it)
      if (!e.blocked) droveMm = e.measured ? e.achieved : -outDoneMm_;
      break;
    case Stage::Made:
    case Stage::GivenUp: break;
  }
  stage_ = Stage::GivenUp;
  return DriveAction::done();
}

}  // namespace nxtmap
