// Boxes in pixels and the pinhole camera's intrinsics: plain values, shared with
// platform/ and apps/ (the camera model's 3D maths is in Camera.hpp).
#pragma once

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

// Axis-aligned box in image pixels; (x, y) is the top-left corner.
struct Box {
  float x = 0.f, y = 0.f, w = 0.f, h = 0.f;  // [px]
  bool empty() const { return !(w > 0.f) || !(h > 0.f); }
  float area() const { return empty() ? 0.f : w * h; }
};

// b grown by `by` of its width and height on each side, about its centre.
inline Box grow(const Box& b, float by) {
  return Box{b.x - by * b.w, b.y - by * b.h, b.w * (1.f + 2.f * by), b.h * (1.f + 2.f * by)};
}

// Intersection over union; 0 when either box is empty (the paper's overlap).
inline float overlap(const Box& a, const Box& b) {
  if (a.empty() || b.empty()) return 0.f;
  const float x0 = a.x > b.x ? a.x : b.x;
  const float y0 = a.y > b.y ? a.y : b.y;
  const float x1 = (a.x + a.w) < (b.x + b.w) ? (a.x + a.w) : (b.x + b.w);
  const float y1 = (a.y + a.h) < (b.y + b.h) ? (a.y + a.h) : (b.y + b.h);
  if (x1 <= x0 || y1 <= y0) return 0.f;
  const float inter = (x1 - x0) * (y1 - y0);
  return inter / (a.area() + b.area() - inter);
}

// A rectangle of whole pixels, [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [px]
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
};

// The pixel rectangle covering box b, clipped to w x h (may be empty).
inline PixelRect clipBox(const Box& b, int w, int h) {
  PixelRect r;
  r.x0 = fmath::floorToInt(b.x);
  r.y0 = fmath::floorToInt(b.y);
  r.x1 = fmath::floorToInt(b.x + b.w) + 1;
  r.y1 = fmath::floorToInt(b.y + b.h) + 1;
  if (r.x0 < 0) r.x0 = 0;
  if (r.y0 < 0) r.y0 = 0;
  if (r.x1 > w) r.x1 = w;
  if (r.y1 > h) r.y1 = h;
  if (r.x1 < r.x0) r.x1 = r.x0;
  if (r.y1 < r.y0) r.y1 = r.y0;
  return r;
}

// The smallest rectangle holding a and b (either may be empty).
inline PixelRect unite(const PixelRect& a, const PixelRect& b) {
  if (a.width() <= 0 || a.height() <= 0) return b;
  if (b.width() <= 0 || b.height() <= 0) return a;
  return PixelRect{a.x0 < b.x0 ? a.x0 : b.x0, a.y0 < b.y0 ? a.y0 : b.y0, a.x1 > b.x1 ? a.x1 : b.x1,
                   a.y1 > b.y1 ? a.y1 : b.y1};
}

// Whether window b lies mostly inside the imageW x imageH image (tuning::search::kInside
// of its area): a window half outside scores on whatever its features read there, so
// the lost search and the estimate's contrast ring take only such windows.
inline bool insideEnough(const Box& b, int imageW, int imageH) {
  const PixelRect c = clipBox(b, imageW, imageH);
  return static_cast<float>(c.width() * c.height()) >= tuning::search::kInside * b.area();
}

// Pinhole intrinsics of the colour image (depth is registered to it).
// Camera coordinates [mm]: x right, y down, z forward along the optical axis.
struct CameraIntrinsics {
  float fx = 0.f, fy = 0.f;  // focal lengths [px]
  float cx = 0.f, cy = 0.f;  // principal point [px]
  bool valid() const { return fx > 0.f && fy > 0.f; }
};

// Kinect v1 colour camera defaults (the NYU calibration, also close to TUM fr1).
inline constexpr CameraIntrinsics kKinectV1Intrinsics{518.0f, 519.0f, 325.5f, 253.5f};

}  // namespace cuetrack
