// Whether this frame's estimate is a miss (beyond the paper; with `lostDetection`): not
// the target, whatever its confidence. A miss is not learnt and counts as a frame of
// zero confidence for the lost detector.
#pragma once

#include "cuetrack/core/guards/DepthGuard.hpp"

namespace cuetrack {

struct MissRule {
  // What the rule reads of one frame's estimate.
  struct Inputs {
    bool is3d = false;
    bool wasLost = false;      // lost before this frame
    bool onProbation = false;  // LostDetector: found again, not yet confirmed
    float depthMm = 0.f;       // 3D: the estimate's depth
    float contrast = 0.f;      // PeakContrast::of at the estimate
    // The appearance cue answers well below its usual peak on the target (PeakLevel).
    bool unlikeTarget = false;
  };
  // 3D, tracking: the estimate jumped well in front of or behind the confirmed depth
  // (DepthGuard::jumped: the depth correction put the cloud on something passing in front,
  // or on the background). Always: it does not stand out from the windows beside it
  // (PeakContrast::flat: a plain wall, a cloud drifted onto background). 3D, lost or on
  // probation: found again too far off the confirmed depth (DepthGuard::implausibleFind:
  // the floor, a wall behind, a look-alike in front). On probation: unlike the target
  // (`unlikeTarget`), whatever the classifier says.
  static bool miss(const Inputs& in, const DepthGuard& guard);
};

}  // namespace cuetrack
