// What the tracker sees each step: views of caller-owned pixels, no copies.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"

namespace cuetrack {

struct Frame {
  RgbView rgb;                    // colour, required
  DepthView depthMm;              // [mm] registered to rgb, 0 = none; empty() when no depth
  uint64_t timeUs = 0;            // capture time [us], monotonic within a sequence
  CameraIntrinsics intrinsics{};  // of rgb; needed by the 3D state space

  bool hasDepth() const { return !depthMm.empty(); }
};

}  // namespace cuetrack
