// A frame larger than the tracker's working size (kMaxImageWidth x kMaxImageHeight) is
// scaled down once, by its source, into the fixed-size slot (aspect kept). FrameScale
// says how: the source's own size and the size in the slot, and maps boxes and intrinsics
// between the two. Everything in a FrameSlot (image, ground truth, intrinsics) is in the
// slot's pixels; boxes that cross the program's edge (--box, a serial START, CSV, stdout,
// serial, MAVLink) are in the source's own pixels, mapped here and nowhere else.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

struct FrameScale {
  // All 0: not scaled (the source's pixels are the slot's), the default of every source.
  int sourceWidthPx = 0, sourceHeightPx = 0;  // the source's own frame
  int widthPx = 0, heightPx = 0;              // the frame in the slot

  // The largest size within maxW x maxH with the source's aspect; unscaled when it fits.
  static FrameScale fit(int sourceW, int sourceH, int maxW = kMaxImageWidth,
                        int maxH = kMaxImageHeight) {
    FrameScale s;
    if (sourceW <= maxW && sourceH <= maxH) return s;
    s.sourceWidthPx = sourceW;
    s.sourceHeightPx = sourceH;
    // Compare w * maxH against h * maxW in integers: the tighter side decides.
    if (static_cast<long long>(sourceW) * maxH >= static_cast<long long>(sourceH) * maxW) {
      s.widthPx = maxW;
      s.heightPx =
          static_cast<int>((static_cast<long long>(sourceH) * maxW + sourceW / 2) / sourceW);
    } else {
      s.heightPx = maxH;
      s.widthPx =
          static_cast<int>((static_cast<long long>(sourceW) * maxH + sourceH / 2) / sourceH);
    }
    if (s.widthPx < 1) s.widthPx = 1;
    if (s.heightPx < 1) s.heightPx = 1;
    return s;
  }

  bool scaled() const { return widthPx > 0 && heightPx > 0; }
  // Source pixels per slot pixel, per axis (1 when not scaled).
  float xFactor() const {
    return scaled() ? static_cast<float>(sourceWidthPx) / static_cast<float>(widthPx) : 1.f;
  }
  float yFactor() const {
    return scaled() ? static_cast<float>(sourceHeightPx) / static_cast<float>(heightPx) : 1.f;
  }
  // The source's size given the slot's (the same when not scaled).
  int sourceWidth(int slotWidthPx) const { return scaled() ? sourceWidthPx : slotWidthPx; }
  int sourceHeight(int slotHeightPx) const { return scaled() ? sourceHeightPx : slotHeightPx; }

  Box toSource(const Box& b) const {
    const float sx = xFactor(), sy = yFactor();
    return Box{b.x * sx, b.y * sy, b.w * sx, b.h * sy};
  }
  Box toSlot(const Box& b) const {
    const float sx = xFactor(), sy = yFactor();
    return Box{b.x / sx, b.y / sy, b.w / sx, b.h / sy};
  }
  CameraIntrinsics toSource(const CameraIntrinsics& k) const {
    const float sx = xFactor(), sy = yFactor();
    return CameraIntrinsics{k.fx * sx, k.fy * sy, k.cx * sx, k.cy * sy};
  }
};

}  // namespace cuetrack
