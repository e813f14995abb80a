// Where a synthetic scene's objects go in a real RGB-D still (the still: source): the
// whole scene is moved by one offset, so the objects keep their sizes, their motions and
// their places relative to each other, and the target comes to stand on a chosen pixel,
// a chosen gap in front of the real surface seen there.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

// The still's depth at pixel (u, v) [mm]: the median of the readings within radiusPx
// (Chebyshev), holes (0) left out; 0 when there is none.
uint16_t stillDepthNear(const uint16_t* depthMm, int width, int height, int u, int v,
                        int radiusPx = 5);

// How far the target reaches behind its centre at t = 0 [mm]: a cylinder's radius, a box's
// half-depth turned by its yaw at t = 0.
float targetBackMm(const SceneSpec& spec);

// Moves every object of *spec by one offset so that the target's motion start
// (MotionSpec::startMm, the centre its motion is about) lies on the ray through pixel
// (u, v) with its back gapMm in front of the still's depth there (stillDepthNear).
// k: the still's intrinsics. False, with one line in err, when the still has no reading
// near (u, v), or the target would come nearer than spec->minDepthMm.
bool placeInStill(SceneSpec* spec, const uint16_t* depthMm, int width, int height,
                  const CameraIntrinsics& k, float u, float v, float gapMm, char* err,
                  size_t errLen);

}  // namespace cuetrack
