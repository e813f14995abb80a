// The box a new track starts from (Tracker::init): the box asked for, intersected with
// the image, or why there is none.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/InitError.hpp"

namespace cuetrack {

// `box` on colour image `rgb`: None and *target, the box within the image; else why not
// (no colour, an image over kMaxImageWidth x kMaxImageHeight, an empty box, a box off
// the image, a target under kMinTargetPx a side).
InitError initTarget(const RgbView& rgb, const Box& box, Box* target);

}  // namespace cuetrack
