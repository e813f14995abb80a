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
  float x = 0.f, y = 0.f;  // (gx, gy) or (alpha, beta), in the kind's unit
  bool valid = false;
  float angle() const { return fmath::fastAtan2(y, x); }  // [rad] in [0, 2 pi)
  float mag() const { return fmath::sqrtf(x * x + y * y); }
  float magSquared() const { return x * x + y * y; }
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
  const T* r0 = t + static_cast<std::ptrdiff_t>(ys[0]) * stride;
  const T* r1 = t + static_cast<std::ptrdiff_t>(ys[1]) * stride;
  const T* r2 = t + static_cast<std::ptrdiff_t>(ys[2]) * stride;
  const T c0 = r0[xs[0]], c1 = r0[xs[1]], c2 = r0[xs[2]];
  const T c3 = r1[xs[0]], c4 = r1[xs[1]], c5 = r1[xs[2]];
  const T c6 = r2[xs[0]], c7 = r2[xs[1]], c8 = r2[xs[2]];
  q[0] = static_cast<float>(static_cast<T>(c4 - c3 - c1 + c0));
  q[1] = static_cast<float>(static_cast<T>(c5 - c4 - c2 + c1));
  q[2] = static_cast<float>(static_cast<T>(c7 - c6 - c4 + c3));
  q[3] = static_cast<float>(static_cast<T>(c8 - c7 - c5 + c4));
}

template <typename T>
inline float rect(const T* t, int stride, int x0, int y0, int x1, int y1) {
  return static_cast<float>(static_cast<T>(at(t, stride, x1, y1) - at(t, stride, x0, y1) -
                                           at(t, stride, x1, y0) + at(t, stride, x0, y0)));
}

}  // namespace detail

// Pixel rectangle [x0, x1) x [y0, y1) of feature f in window `win` (frame px), in the
// tables' own coordinates and clipped to them, with an even width and height so the
// halves are equal. False when less than 2x2 px remain (a gradient needs two halves).
template <typename U, typename S>
inline bool featureRect(const Feature& f, const Box& win, const ChannelTables<U, S>& t, int* x0,
                        int* y0, int* x1, int* y1) {
  const float fx0 = win.x + f.x * win.w - static_cast<float>(t.originX);
  const float fy0 = win.y + f.y * win.h - static_cast<float>(t.originY);
  // Round half up without a branch (valid above -4096 px).
  int a = static_cast<int>(fx0 + 4096.5f) - 4096;
  int b = static_cast<int>(fx0 + f.w * win.w + 4096.5f) - 4096;
  int c = static_cast<int>(fy0 + 4096.5f) - 4096;
  int d = static_cast<int>(fy0 + f.h * win.h + 4096.5f) - 4096;
  if (b < a + 2) b = a + 2;  // tiny windows: at least two pixels per axis
  if (d < c + 2) d = c + 2;
  if (a < 0) a = 0;
  if (c < 0) c = 0;
  if (b > t.width) b = t.width;
  if (d > t.height) d = t.height;
  *x0 = a;
  *y0 = c;
  *x1 = a + ((b - a) & ~1);
  *y1 = c + ((d - c) & ~1);
  return b - a >= 2 && d - c >= 2;
}

inline Response vec(float x, float y) {
  Response r;
  r.x = x;
  r.y = y;
  r.valid = true;
  return r;
}

// The response of a feature of kind K on the window `win` (frame px for frames; the
// patch's own [0, size]^2 for examples).
template <FeatureKind K, typename U, typename S>
inline Response evaluateKind(const Feature& f, const Box& win, const ChannelTables<U, S>& t) {
  int x0, y0, x1, y1;
  if (!featureRect(f, win, t, &x0, &y0, &x1, &y1)) return Response{};
  const float area = static_cast<float>((x1 - x0) * (y1 - y0));
  const float invArea = 1.f / area;
  if constexpr (K == FeatureKind::Colour) {
    const float a2 = detail::rect(t.alpha2, t.stride, x0, y0, x1, y1);
    const float b = detail::rect(t.beta, t.stride, x0, y0, x1, y1);
    return vec(0.5f * a2 * invArea, 0.866025404f * b * invArea);
  }
  const int xs[3] = {x0, (x0 + x1) >> 1, x1};
  const int ys[3] = {y0, (y0 + y1) >> 1, y1};
  float q[4];
  if constexpr (K == FeatureKind::Gray) {
    // Equal halves: mean(right) - mean(left) = (R - L) / (A / 2).
    detail::quadrants(t.gray, t.stride, xs, ys, q);
    const float k = 2.f * invArea;
    return vec(((q[1] + q[3]) - (q[0] + q[2])) * k, ((q[2] + q[3]) - (q[0] + q[1])) * k);
  }
  // Depth: means over valid pixels only; a half that is less than half valid is no
  // measurement, so holes (0 mm) never make a gradient.
  float n[4];
  detail::quadrants(t.depth, t.stride, xs, ys, q);
  detail::quadrants(t.count, t.stride, xs, ys, n);
  const float nl = n[0] + n[2], nr = n[1] + n[3], nt = n[0] + n[1], nb = n[2] + n[3];
  const float minValid = 0.25f * area;  // half of a half
  if (nl < minValid || nr < minValid || nt < minValid || nb < minValid) return Response{};
  const float l = q[0] + q[2], r = q[1] + q[3], tp = q[0] + q[1], bt = q[2] + q[3];
  return vec((r * nl - l * nr) / (nl * nr), (bt * nt - tp * nb) / (nt * nb));
}

template <typename U, typename S>
inline Response evaluate(const Feature& f, const Box& win, const ChannelTables<U, S>& t) {
  switch (f.kind) {
    case FeatureKind::Gray:
      return evaluateKind<FeatureKind::Gray>(f, win, t);
    case FeatureKind::Depth:
      return evaluateKind<FeatureKind::Depth>(f, win, t);
    case FeatureKind::Colour:
      break;
  }
  return evaluateKind<FeatureKind::Colour>(f, win, t);
}

}  // namespace cuetrack
