#include "cuetrack/core/model/NegativeSampler.hpp"

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack {

NegativeSampler::Params NegativeSampler::paramsOf(const TrackerConfig& c) {
  Params p;
  p.anchored2d = c.anchoredNegatives2d;
  return p;
}

Box NegativeSampler::next(int k, const Box& around, const PixelRect& roi, const Cylinder* cylinder,
                          Rng& rng) const {
  // Every other negative is a near miss (shifted and/or rescaled, overlap < 0.5) so the
  // classifier learns to localise; the rest are background within the range.
  const bool near = (k & 1) == 0;
  if (near && (k & 2) == 0 && _p.shrunkScale > 0.f) {
    // A window shrunk or grown along one axis or both: teaches that the target's border
    // belongs at the window's border (a window inside the target otherwise scores as well
    // as the right one, and the estimate shrinks). Shrunk or grown (1/scale) alike, so
    // neither direction is favoured. In 2D, anchored at the estimate's start, centre or
    // end along each axis: a window on the target's most distinctive corner (a panda's
    // head) otherwise outscores the whole target, and the size drifts there
    // (docs/algorithm.md). In 3D the cylinder and the depth set the size.
    const float sc = rng.below(2) == 0 ? _p.shrunkScale : 1.f / _p.shrunkScale;
    const uint32_t mode = rng.below(3);
    const float sw = mode == 1 ? 1.f : sc, sh = mode == 0 ? 1.f : sc;
    float ax = 0.5f, ay = 0.5f;
    if (cylinder == nullptr && _p.anchored2d) {
      ax = 0.5f * static_cast<float>(rng.below(3));
      ay = 0.5f * static_cast<float>(rng.below(3));
    }
    return Box{around.x + ax * around.w * (1.f - sw), around.y + ay * around.h * (1.f - sh),
               around.w * sw, around.h * sh};
  }
  if (near && (k & 2) != 0 && _p.shiftedFraction > 0.f) {
    // The estimate shifted along one axis, either way: pins the position likewise.
    const float d = (rng.below(2) == 0 ? -1.f : 1.f) * _p.shiftedFraction;
    const bool alongX = rng.below(2) == 0;
    return Box{around.x + (alongX ? d * around.w : 0.f), around.y + (alongX ? 0.f : d * around.h),
               around.w, around.h};
  }
  const float rx0 = static_cast<float>(roi.x0), ry0 = static_cast<float>(roi.y0);
  const float rx1 = static_cast<float>(roi.x1), ry1 = static_cast<float>(roi.y1);
  const float maxOverlap = near ? _p.nearOverlap : kMaxOverlap;
  Box b = around;
  for (int attempt = 0; attempt < 12; ++attempt) {
    const float range = near ? 0.6f : kRange;
    const float cx = around.x + 0.5f * around.w + rng.uniform(-range, range) * around.w;
    const float cy = around.y + 0.5f * around.h + rng.uniform(-range, range) * around.h;
    float w = around.w, h = around.h;
    bool sized = false;
    if (cylinder != nullptr && !near) {
      // The size the target would have at the depth found there (paper 2.1).
      const Box probe{cx - 2.f, cy - 2.f, 4.f, 4.f};
      const float d =
          cylinder->channels->meanDepthMm(clipBox(probe, cylinder->imageW, cylinder->imageH));
      if (d > 0.f) {
        const float z = d + 0.5f * cylinder->diameterMm;
        w = cylinder->k.fx * cylinder->diameterMm / z;
        h = cylinder->k.fy * cylinder->heightMm / z;
        sized = true;
      }
    }
    if (!sized) {
      const float s = fmath::fastExp((near ? 0.4f : 0.15f) * rng.gaussian());
      const float a = near ? fmath::fastExp(0.25f * rng.gaussian()) : 1.f;  // aspect
      w *= s * a;
      h *= s / a;
    }
    if (w > rx1 - rx0) w = rx1 - rx0;
    if (h > ry1 - ry0) h = ry1 - ry0;
    if (w < kMinWindowPx) w = kMinWindowPx;
    if (h < kMinWindowPx) h = kMinWindowPx;
    b = Box{fmath::clampf(cx - 0.5f * w, rx0, rx1 - w), fmath::clampf(cy - 0.5f * h, ry0, ry1 - h),
            w, h};
    if (overlap(b, around) < maxOverlap) break;
  }
  return b;
}

}  // namespace cuetrack
