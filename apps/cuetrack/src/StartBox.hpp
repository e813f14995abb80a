// A start request (a pixel box from cuetrack's protocol; a normalised rectangle or
// point from MAVLink) turned into the pixel box the tracker starts on, on the frame it
// starts on: a point becomes a square around it, sized from the depth there when there
// is depth (an object of kPointTargetMm at that distance), else from the radius given,
// else kPointDefaultWidthFraction of the image.
#pragma once

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/platform/TrackLink.hpp"

namespace cuetrack::app {

inline constexpr float kPointTargetMm = 400.f;             // a person's torso, a landing pad
inline constexpr float kPointDefaultWidthFraction = 0.1f;  // no depth, no radius
inline constexpr float kPointMinSidePx = 16.f;             // twice the tracker's smallest window

Box startBoxPx(const platform::StartRequest& request, const Frame& frame);

}  // namespace cuetrack::app
