// The order in which the particles' windows are scored: row band by row band (a
// counting sort on each window's top edge, in 8 px bands from the ROI's top), so that
// the feature reads of consecutive windows share cache lines. The same scores in any
// order; only the speed changes.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

class ScanOrder {
 public:
  static constexpr int kBandShift = 3;  // 8 px bands
  static constexpr int kBands = 64;     // the last band takes every lower window
  // The indices 0..n-1 of `boxes` (n of them), by band of box.y - roiY0 (stable within
  // a band).
  const uint16_t* sort(Span<const Box> boxes, int roiY0);

 private:
  uint8_t _band[kMaxParticles];
  uint16_t _order[kMaxParticles];
};

}  // namespace cuetrack
