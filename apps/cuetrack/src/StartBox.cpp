#include "StartBox.hpp"

#include <cmath>

namespace cuetrack::app {
namespace {

constexpr int kDepthWindowHalfPx = 2;  // the depth at a point: mean of the valid 5x5 around it

// Mean valid depth [mm] in a small window around (x, y); 0 when none.
float depthNearMm(const DepthView& d, float xPx, float yPx) {
  // Outside the image (or not a number): no depth there, and no int overflow below.
  if (d.empty() || !(xPx >= 0.f) || !(yPx >= 0.f) || xPx >= static_cast<float>(d.width) ||
      yPx >= static_cast<float>(d.height))
    return 0.f;
  const int cx = static_cast<int>(xPx), cy = static_cast<int>(yPx);
  double sum = 0;
  int n = 0;
  for (int y = cy - kDepthWindowHalfPx; y <= cy + kDepthWindowHalfPx; ++y) {
    for (int x = cx - kDepthWindowHalfPx; x <= cx + kDepthWindowHalfPx; ++x) {
      if (x < 0 || y < 0 || x >= d.width || y >= d.height) continue;
      const uint16_t v = d.at(x, y);
      if (v == 0) continue;
      sum += v;
      ++n;
    }
  }
  return n > 0 ? static_cast<float>(sum / n) : 0.f;
}

}  // namespace

Box startBoxPx(const platform::StartRequest& request, const Frame& frame) {
  using Kind = platform::StartRequest::Kind;
  const float w = static_cast<float>(frame.rgb.width), h = static_cast<float>(frame.rgb.height);
  switch (request.kind) {
    case Kind::BoxPx:
      return request.box;
    case Kind::BoxNormalised:
      return Box{request.box.x * w, request.box.y * h, request.box.w * w, request.box.h * h};
    case Kind::PointNormalised:
      break;
  }
  const float xPx = request.pointX * w, yPx = request.pointY * h;
  float sidePx = kPointDefaultWidthFraction * w;
  const float depthMm = depthNearMm(frame.depthMm, xPx, yPx);
  const float fx = frame.intrinsics.valid() ? frame.intrinsics.fx : kKinectV1Intrinsics.fx;
  if (depthMm > 0.f) {
    sidePx = fx * kPointTargetMm / depthMm;
  } else if (request.radius > 0.f) {
    sidePx = 2.f * request.radius * w;
  }
  const float maxSidePx = 0.5f * (w < h ? w : h);
  sidePx = sidePx < kPointMinSidePx ? kPointMinSidePx : sidePx;
  sidePx = sidePx > maxSidePx ? maxSidePx : sidePx;
  return Box{xPx - 0.5f * sidePx, yPx - 0.5f * sidePx, sidePx, sidePx};
}

}  // namespace cuetrack::app
