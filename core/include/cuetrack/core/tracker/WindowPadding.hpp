// Small targets (beyond the paper). A feature's halves lie on a 32 x 32 cell grid over
// the window, and on a window of a few pixels most of them round to nothing, so a
// target smaller than tuning::kMinTrackedSidePx along an axis is tracked on a window
// padded with the context around it, centred on it; the box reported is the window
// shrunk back by the same factors. Aerial and far-away robot footage has 6-10 px
// targets; larger targets are tracked on their own box (factors 1).
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

struct WindowPadding {
  float sx = 1.f, sy = 1.f;  // window side / target side, >= 1

  static WindowPadding forTarget(const Box& target) {
    constexpr float m = tuning::kMinTrackedSidePx;
    WindowPadding p;
    if (target.w > 0.f && target.w < m) p.sx = m / target.w;
    if (target.h > 0.f && target.h < m) p.sy = m / target.h;
    return p;
  }
  Box toWindow(const Box& target) const { return scaled(target, sx, sy); }
  Box toTarget(const Box& window) const { return scaled(window, 1.f / sx, 1.f / sy); }

 private:
  // b scaled about its centre; b itself when both factors are 1 (bit for bit).
  static Box scaled(const Box& b, float fx, float fy) {
    if (fx == 1.f && fy == 1.f) return b;
    const float w = b.w * fx, h = b.h * fy;
    return Box{b.x + 0.5f * (b.w - w), b.y + 0.5f * (b.h - h), w, h};
  }
};

}  // namespace cuetrack
