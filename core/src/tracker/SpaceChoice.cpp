#include "cuetrack/core/tracker/SpaceChoice.hpp"

#include "cuetrack/core/guards/Gate.hpp"

namespace cuetrack {

SpaceChoice SpaceChoice::of(const TrackerConfig& config, const Frame& frame, const Box& b,
                            DepthMedian& median) {
  SpaceChoice s;
  s.is3d = config.stateSpace == StateSpace::Cylinder3d;
  s.depthFeatures = config.useDepth;
  if (s.is3d || s.depthFeatures) {
    const bool depthOk = frame.hasDepth() && frame.depthMm.width == frame.rgb.width &&
                         frame.depthMm.height == frame.rgb.height;
    InitError why = InitError::None;
    if (!depthOk) {
      why = InitError::NoDepth;
    } else if (s.is3d && !frame.intrinsics.valid()) {
      why = InitError::NoIntrinsics;
    } else if (s.is3d && !(b.w < frame.intrinsics.fx)) {
      // The init rule D = w s / (fx - w/2) needs w < 2 fx, and a cylinder whose silhouette
      // spans fx px or more would be wider than it is far (the size adaptation's bound too).
      why = InitError::BoxTooWideFor3d;
    } else if (s.is3d && !median.of(frame.depthMm, b, &s.surfaceMm)) {
      why = InitError::NoDepth;  // none valid inside the box
    }
    if (why != InitError::None) {
      if (!config.fallbackTo2d) {
        s.error = why;
        return s;
      }
      s.is3d = false;
      s.depthFeatures = false;
      s.fellBack = true;
      s.why = why;
    }
  }
  s.numWeak = config.numWeakClassifiers;
  s.lostAfter = LostDetector{}.lostAfter;
  if (s.fellBack) {
    if (config.numWeakClassifiers2d > 0) s.numWeak = config.numWeakClassifiers2d;
    if (config.lostAfter2d > 0) s.lostAfter = config.lostAfter2d;
  }
  return s;
}

}  // namespace cuetrack
