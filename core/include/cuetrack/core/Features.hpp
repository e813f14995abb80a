// The three feature kinds of the paper, each a rectangle in normalised window
// coordinates [0,1]^2 evaluated in O(1) on integral tables (see docs/algorithm.md):
//   Gray   gradient of grey level: gx = mean(right half) - mean(left half),
//          gy = mean(bottom half) - mean(top half) [grey levels 0..255]
//   Depth  the same on depth [mm], means over valid pixels only; a half with fewer
//          than half its pixels valid gives no measurement (Response::valid = false)
//   Colour mean (alpha, beta) over the rectangle, alpha = (2R - G - B)/2,
//          beta = sqrt(3)/2 (G - B), with R, G, B in grey levels 0..255
// A Response is then (angle in [0, 2 pi), magnitude): atan2(gy, gx) and |g| for the
// gradients, (H2, C2) for colour. Frame tables and example patches are read through
// the same code (ChannelTables), so a feature answers the same way on both.
#pragma once

#include <cstdint>

#include "cuetrack/core/FastMath.hpp"
#include "cuetrack/core/Geometry.hpp"

namespace cuetrack {

enum class FeatureKind : uint8_t { Gray = 0, Depth = 1, Colour = 2 };

struct Feature {
  float x = 0.f, y = 0.f, w = 1.f, h = 1.f;  // normalised to the window, inside [0,1]^2
  FeatureKind kind = FeatureKind::Gray;
  bool isStatic = false;  // static features never leave the pool
};

struct Response {
  float angle = 0.f;  // [rad] in [0, 2 pi)
  float mag = 0.f;    // grey levels, mm, or chroma (grey levels)
  bool valid = false;
};

// Read-only views of the integral tables of one image region. U holds gray, depth
// and count sums, S the signed colour sums: uint32/int32 for frames (Integral.hpp),
// float for the training examples' small patches. Cell (x, y) sums [0,x) x [0,y).
template <typename U, typename S>
struct ChannelTables {
  const U* gray = nullptr;
  const S* alpha2 = nullptr;     // 2 alpha = 2R - G - B
  const S* beta = nullptr;       // G - B (beta = sqrt(3)/2 of it)
  const U* depth = nullptr;      // [mm], 0 where invalid
  const U* count = nullptr;      // valid depth pixels (fraction per cell in patches)
  int stride = 0;                // cells between table rows
  int width = 0, height = 0;     // image size [px]; tables are (w+1) x (h+1)
  int originX = 0, originY = 0;  // where pixel (0, 0) of the tables lies in frame px
};

using FrameTables = ChannelTables<uint32_t, int32_t>;
using PatchTables = ChannelTables<float, float>;

namespace detail {

template <typename T>
inline T at(const T* t, int stride, int x, int y) {
  return t[static_cast<std::ptrdiff_t>(y) * stride + x];
}

// Sums of the four quadrants split at (xm, ym): q[0] top-left, q[1] top-right,
// q[2] bottom-left, q[3] bottom-right. Unsigned tables wrap exactly (Integral.hpp).
template <typename T>
inline void quadrants(const T* t, int stride, const int xs[3], const int ys[3], float q[4]) {
  T c[9];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) c[j * 3 + i] = at(t, stride, xs[i], ys[j]);
  q[0] = static_cast<float>(static_cast<T>(c[4] - c[3] - c[1] + c[0]));
  q[1] = static_cast<float>(static_cast<T>(c[5] - c[4] - c[2] + c[1]));
  q[2] = static_cast<float>(static_cast<T>(c[7] - c[6] - c[4] + c[3]));
  q[3] = static_cast<float>(static_cast<T>(c[8] - c[7] - c[5] + c[4]));
}

template <typename T>
inline float rect(const T* t, int stride, int x0, int y0, int x1, int y1) {
  return static_cast<float>(static_cast<T>(at(t, stride, x1, y1) - at(t, stride, x0, y1) -
                                           at(t, stride, x1, y0) + at(t, stride, x0, y0)));
}

}  // namespace detail

// Pixel rectangle [x0, x1) x [y0, y1) of feature f in window `win` (frame px), in the
// tables' own coordinates and clipped to them. False when less than 2x2 px remain
// (a gradient needs two halves per axis).
template <typename U, typename S>
inline bool featureRect(const Feature& f, const Box& win, const ChannelTables<U, S>& t, int* x0,
                        int* y0, int* x1, int* y1) {
  const float fx0 = win.x + f.x * win.w - static_cast<float>(t.originX);
  const float fy0 = win.y + f.y * win.h - static_cast<float>(t.originY);
  int a = fmath::roundToInt(fx0), b = fmath::roundToInt(fx0 + f.w * win.w);
  int c = fmath::roundToInt(fy0), d = fmath::roundToInt(fy0 + f.h * win.h);
  if (b < a + 2) b = a + 2;  // tiny windows: at least two pixels per axis
  if (d < c + 2) d = c + 2;
  if (a < 0) a = 0;
  if (c < 0) c = 0;
  if (b > t.width) b = t.width;
  if (d > t.height) d = t.height;
  *x0 = a;
  *y0 = c;
  *x1 = b;
  *y1 = d;
  return b - a >= 2 && d - c >= 2;
}

inline Response polar(float gx, float gy) {
  Response r;
  r.angle = fmath::fastAtan2(gy, gx);
  r.mag = fmath::sqrtf(gx * gx + gy * gy);
  r.valid = true;
  return r;
}

// The response of feature f on the window `win` (frame px for frames; the patch's
// own [0, size]^2 for examples).
template <typename U, typename S>
inline Response evaluate(const Feature& f, const Box& win, const ChannelTables<U, S>& t) {
  int x0, y0, x1, y1;
  if (!featureRect(f, win, t, &x0, &y0, &x1, &y1)) return Response{};
  if (f.kind == FeatureKind::Colour) {
    const float area = static_cast<float>((x1 - x0) * (y1 - y0));
    const float a2 = detail::rect(t.alpha2, t.stride, x0, y0, x1, y1);
    const float b = detail::rect(t.beta, t.stride, x0, y0, x1, y1);
    const float alpha = 0.5f * a2 / area;
    const float beta = 0.866025404f * b / area;
    return polar(alpha, beta);
  }
  const int xs[3] = {x0, (x0 + x1) >> 1, x1};
  const int ys[3] = {y0, (y0 + y1) >> 1, y1};
  const float wl = static_cast<float>(xs[1] - xs[0]), wr = static_cast<float>(xs[2] - xs[1]);
  const float ht = static_cast<float>(ys[1] - ys[0]), hb = static_cast<float>(ys[2] - ys[1]);
  float q[4];
  if (f.kind == FeatureKind::Gray) {
    detail::quadrants(t.gray, t.stride, xs, ys, q);
    const float h = ht + hb, w = wl + wr;
    const float gx = (q[1] + q[3]) / (wr * h) - (q[0] + q[2]) / (wl * h);
    const float gy = (q[2] + q[3]) / (hb * w) - (q[0] + q[1]) / (ht * w);
    return polar(gx, gy);
  }
  // Depth: means over valid pixels only; a half that is less than half valid is no
  // measurement, so holes (0 mm) never make a gradient.
  float n[4];
  detail::quadrants(t.depth, t.stride, xs, ys, q);
  detail::quadrants(t.count, t.stride, xs, ys, n);
  const float h = ht + hb, w = wl + wr;
  const float nl = n[0] + n[2], nr = n[1] + n[3], nt = n[0] + n[1], nb = n[2] + n[3];
  if (nl < 0.5f * wl * h || nr < 0.5f * wr * h || nt < 0.5f * ht * w || nb < 0.5f * hb * w)
    return Response{};
  const float gx = (q[1] + q[3]) / nr - (q[0] + q[2]) / nl;
  const float gy = (q[2] + q[3]) / nb - (q[0] + q[1]) / nt;
  return polar(gx, gy);
}

}  // namespace cuetrack
