#include "cuetrack/drivers/StillPlacement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cuetrack {

uint16_t stillDepthNear(const uint16_t* depthMm, int width, int height, int u, int v,
                        int radiusPx) {
  constexpr int kMaxRadius = 7;  // the samples live on the stack: at most 15 x 15
  const int r = radiusPx < 0 ? 0 : (radiusPx > kMaxRadius ? kMaxRadius : radiusPx);
  uint16_t samples[(2 * kMaxRadius + 1) * (2 * kMaxRadius + 1)];
  int n = 0;
  for (int y = std::max(0, v - r); y <= std::min(height - 1, v + r); ++y)
    for (int x = std::max(0, u - r); x <= std::min(width - 1, u + r); ++x)
      if (const uint16_t d = depthMm[y * width + x]) samples[n++] = d;
  if (n == 0) return 0;
  std::nth_element(samples, samples + n / 2, samples + n);
  return samples[n / 2];
}

float targetBackMm(const SceneSpec& spec) {
  const SceneObject& o = spec.objects[spec.targetIndex];
  if (o.shape == ShapeKind::Cylinder) return o.radiusMm;
  const float yaw =
      o.yawRad + (o.yawPeriodS > 0.f ? o.yawAmplitudeRad * std::sin(o.yawPhaseRad) : 0.f);
  return std::fabs(std::sin(yaw)) * o.radiusMm + std::fabs(std::cos(yaw)) * o.halfDepthMm;
}

bool placeInStill(SceneSpec* spec, const uint16_t* depthMm, int width, int height,
                  const CameraIntrinsics& k, float u, float v, float gapMm, char* err,
                  size_t errLen) {
  if (!(u >= 0.f && u < static_cast<float>(width) && v >= 0.f && v < static_cast<float>(height))) {
    std::snprintf(err, errLen, "pixel %g,%g lies outside the %dx%d still", static_cast<double>(u),
                  static_cast<double>(v), width, height);
    return false;
  }
  const uint16_t surfaceMm =
      stillDepthNear(depthMm, width, height, static_cast<int>(u), static_cast<int>(v));
  if (surfaceMm == 0) {
    std::snprintf(err, errLen, "the still has no depth within 5 px of %g,%g (a hole)",
                  static_cast<double>(u), static_cast<double>(v));
    return false;
  }
  const float zMm = static_cast<float>(surfaceMm) - gapMm - targetBackMm(*spec);
  if (zMm < static_cast<float>(spec->minDepthMm)) {
    std::snprintf(err, errLen,
                  "the target would stand at %.0f mm, nearer than %u mm (the surface at %g,%g is "
                  "%u mm away)",
                  static_cast<double>(zMm), spec->minDepthMm, static_cast<double>(u),
                  static_cast<double>(v), surfaceMm);
    return false;
  }
  const float* start = spec->objects[spec->targetIndex].motion.startMm;
  const float offset[3] = {(u - k.cx) / k.fx * zMm - start[0], (v - k.cy) / k.fy * zMm - start[1],
                           zMm - start[2]};
  for (int i = 0; i < spec->numObjects; ++i)
    for (int a = 0; a < 3; ++a) spec->objects[i].motion.startMm[a] += offset[a];
  return true;
}

}  // namespace cuetrack
