// Boxes in pixels and the pinhole camera's intrinsics: plain values, shared with
// platform/ and apps/ (the camera model's 3D maths is in Camera.hpp).
#pragma once

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
