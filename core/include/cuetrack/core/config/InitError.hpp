// Why a track could not start (Tracker::init), or, after a fallback to 2D RGB, why the
// 3D state or depth features were not used (SpaceChoice::why).
#pragma once

#include <cstdint>

namespace cuetrack {

enum class InitError : uint8_t {
  None = 0,
  EmptyBox,         // w or h <= 0
  BoxOutsideImage,  // box does not intersect the image
  BoxTooSmall,      // smaller than kMinTargetPx along a side
  NoColour,         // frame without colour image
  ImageTooLarge,    // larger than kMaxImageWidth x kMaxImageHeight
  NoDepth,          // 3D state space without depth, or no valid depth inside the box
  NoIntrinsics,     // 3D state space without camera intrinsics
  BoxTooWideFor3d,  // 3D state space, box at least fx wide: no upright cylinder projects so
};
const char* toString(InitError e);

}  // namespace cuetrack
