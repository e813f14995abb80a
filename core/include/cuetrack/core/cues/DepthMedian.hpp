// The median of the valid depth inside a box, to 10 mm: where a new 3D track's
// cylinder stands (robust to the background and the holes around the target).
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

class DepthMedian {
 public:
  static constexpr int kBinMm = 10;
  // The bin centre of the median of depthMm's valid pixels (1..kMaxDepthMm) in `box`;
  // false when it has none.
  bool of(const DepthView& depthMm, const Box& box, float* outMm);

 private:
  uint32_t _histogram[kMaxDepthMm / kBinMm + 1] = {};
};

}  // namespace cuetrack
