// Two depth checks of the 3D estimate (beyond the paper; with `lostDetection`):
// - a jump: the estimate's depth lies well in front of or behind where the target was
//   last confirmed (learnt, or found again): the depth correction has put the cloud on
//   something passing in front, or on the background, either of which can look enough
//   like the target to keep the confidence up. It counts as a miss and is not learnt.
// - learning (`learnDepthCheck`): no learning from an estimate more than
//   kLearnMaxChange off a reference that is the confirmed depth, or follows the estimate
//   while it moves smoothly (a target walking away while nothing is learnt) but not when
//   it jumps (a cloud sliding off a low-contrast target onto the wall behind it, which one
//   learnt positive would teach the classifier).
#pragma once

#include "cuetrack/core/Tuning.hpp"

namespace cuetrack {

// Whether depth zMm lies within a factor `ratio` (>= 1) of the reference refMm, either
// way; true while there is no reference (refMm <= 0).
inline bool depthWithin(float zMm, float refMm, float ratio) {
  return refMm <= 0.f || (zMm <= ratio * refMm && zMm * ratio >= refMm);
}

class DepthGuard {
 public:
  void configure(bool learnCheck) { _learnCheck = learnCheck; }
  // A new track at depth zMm.
  void reset(float zMm) { _confirmedMm = _learnRefMm = _prevMm = zMm; }
  bool jumped(float zMm) const {
    constexpr float r = tuning::depthGuard::kJumpRatio;
    return zMm < r * _confirmedMm || r * zMm > _confirmedMm;
  }
  bool learnable(float zMm) const {
    return !_learnCheck || depthWithin(zMm, _learnRefMm, 1.f + tuning::depthGuard::kLearnMaxChange);
  }
  // After the decision on a frame dtS after the last: `confirmed` when the estimate at
  // zMm was learnt or found again, `tracking` when the target is not lost.
  void update(float zMm, bool confirmed, bool tracking, float dtS);
  float confirmedMm() const { return _confirmedMm; }
  float learnReferenceMm() const { return _learnRefMm; }

 private:
  bool _learnCheck = true;
  float _confirmedMm = 0.f;  // the last confirmed depth
  float _learnRefMm = 0.f;   // the learning check's reference
  float _prevMm = 0.f;       // the last frame's estimate depth
};

}  // namespace cuetrack
