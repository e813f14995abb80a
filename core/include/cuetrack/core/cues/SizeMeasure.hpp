// Adaptive cylinder size (beyond the paper; `adaptCylinderSize`): the target's
// silhouette measured in the depth image around the estimate, so D and H can follow a
// target whose width changes as it turns. A few thousand pixel reads, no tables.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack {

struct SilhouetteExtent {
  float widthPx = 0.f;                     // valid when hasWidth
  float heightPx = 0.f;                    // valid when hasHeight
  float centreXPx = 0.f, centreYPx = 0.f;  // the runs' midpoints (image px)
  bool hasWidth = false;
  bool hasHeight = false;
};

// The silhouette's window: the box grown by this x its size per side ...
inline constexpr float kSilhouetteGrow = 0.5f;
// ... or, for the width of a target that has grown wider than that window holds (a flat
// target turning back face-on), by this.
inline constexpr float kSilhouetteWideGrow = 1.5f;

enum class SilhouetteAxes : uint8_t { Both, WidthOnly };

// The extent of the pixels whose depth lies in [nearMm, farMm] (0 = missing: never
// counted) in a window of `box` grown by `grow` x its size per side. Width: the run of
// columns containing the box's centre column in which most valid samples of the box's
// middle rows lie in the slab, bridging gaps of a few px; height likewise with rows
// sampled in the box's middle columns (the middle only: a floor or table the target
// stands on is at its depth too). An axis stays unmeasured when its run reaches the
// window's edge (the target goes on into something at its depth, or leaves the image).
SilhouetteExtent measureSilhouette(const DepthView& depth, const Box& box, float nearMm,
                                   float farMm, float grow = kSilhouetteGrow,
                                   SilhouetteAxes axes = SilhouetteAxes::Both);

// The upright cylinder whose projection is wPx x hPx with its front surface at
// surfaceMm (the tracker's init rule): D = w s / (fx - w / 2), H = h (s + D / 2) / fy.
float cylinderDiameterMm(float wPx, float surfaceMm, const CameraIntrinsics& k);
float cylinderHeightMm(float hPx, float surfaceMm, float diameterMm, const CameraIntrinsics& k);

}  // namespace cuetrack
