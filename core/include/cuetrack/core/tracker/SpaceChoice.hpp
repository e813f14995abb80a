// Where a new track runs (Tracker::init): the 3D cylinder state and depth features the
// configuration asks for, or, with `fallbackTo2d`, 2D RGB when the frame cannot carry them,
// and why; with the 2D fallback's own M and lost-after count.
#pragma once

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/config/InitError.hpp"
#include "cuetrack/core/config/TrackerConfig.hpp"
#include "cuetrack/core/cues/DepthMedian.hpp"

namespace cuetrack {

struct SpaceChoice {
  InitError error = InitError::None;  // no track: the configuration has no fallback
  bool is3d = false;                  // the cylinder state
  bool depthFeatures = false;         // depth gradient features
  bool fellBack = false;              // asked for 3D or depth, runs 2D RGB ...
  InitError why = InitError::None;    // ... because of this
  float surfaceMm = 0.f;              // 3D: the depth the cylinder stands at
  int numWeak = 1;                    // M: numWeakClassifiers, or ...2d in the fallback
  int lostAfter = 1;                  // the lost detector's count: its own, or lostAfter2d

  // For tracking window `window` from `frame` (median: scratch for the surface's depth).
  static SpaceChoice of(const TrackerConfig& config, const Frame& frame, const Box& window,
                        DepthMedian& median);
};

}  // namespace cuetrack
