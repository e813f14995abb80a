// The 3D estimate's depth against where the target was last confirmed (learnt, or found
// again; beyond the paper, with `lostDetection`): an estimate well in front of or behind
// it means the depth correction has put the cloud on something passing in front, or on
// the background, either of which can look enough like the target to keep the
// confidence up. That frame counts as a miss and is not learnt. Likewise a find while
// lost at under 3/4 or over 4/3 of that depth (the floor, a wall behind).
#pragma once

#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

class DepthGuard {
 public:
  // A new track at depth zMm.
  void reset(float zMm) { _confirmedMm = zMm; }
  bool jumped(float zMm) const {
    constexpr float r = tuning::depthGuard::kJumpRatio;
    return zMm < r * _confirmedMm || r * zMm > _confirmedMm;
  }
  // A candidate found again (while lost, or on probation) at zMm is too far off the
  // confirmed depth to be the target, which may have moved in depth while hidden.
  bool implausibleFind(float zMm) const {
    constexpr float r = tuning::depthGuard::kFoundRatio;
    return zMm > r * _confirmedMm || _confirmedMm > r * zMm;
  }
  // The estimate at zMm was learnt or found again.
  void confirm(float zMm) { _confirmedMm = zMm; }
  float confirmedMm() const { return _confirmedMm; }

 private:
  float _confirmedMm = 0.f;  // the last confirmed depth [mm]
};

}  // namespace cuetrack
