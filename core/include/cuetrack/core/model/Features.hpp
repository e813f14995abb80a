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

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/base/Geometry.hpp"

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

// The grid a feature is placed on. A window is cut into kGridCells x kGridCells cells,
// the cells of an example patch (TrainingSet.hpp). A feature's rectangle, and the line
// splitting it into halves, lie on cell edges, and a cell edge lies on the pixel nearest
// to it. So a feature reads the very same pixels whether it is evaluated on the frame or
// on the example patch kept of that window, and the two answers are bit for bit equal:
// the classifier is trained on exactly what it is later asked (docs/algorithm.md).
inline constexpr int kGridCells = 32;

// Round half up without a branch (valid above -4096).
inline int roundHalfUp(float v) {
  return static_cast<int>(v + 4096.5f) - 4096;
}

// Cell edges [c[0], c[2]) of a feature's extent (pos, len) along one axis, split at c[1]:
// at least two cells, an even count, inside [0, kGridCells].
inline void featureCells(float pos, float len, int c[3]) {
  constexpr float g = static_cast<float>(kGridCells);
  int a = roundHalfUp(pos * g);
  int b = roundHalfUp((pos + len) * g);
  if (a < 0) a = 0;
  if (a > kGridCells - 2) a = kGridCells - 2;
  if (b < a + 2) b = a + 2;
  if (b > kGridCells) b = kGridCells;
  b = a + ((b - a) & ~1);
  c[0] = a;
  c[1] = (a + b) >> 1;
  c[2] = b;
}

// The fraction of the window at each of a feature's cell edges, x and y (k / kGridCells,
// exact): what the SIMD cell coders broadcast once per feature.
inline void featureEdgeFractions(const Feature& f, float fx[3], float fy[3]) {
  int cx[3], cy[3];
  featureCells(f.x, f.w, cx);
  featureCells(f.y, f.h, cy);
  for (int e = 0; e < 3; ++e) {
    fx[e] = static_cast<float>(cx[e]) * (1.f / static_cast<float>(kGridCells));
    fy[e] = static_cast<float>(cy[e]) * (1.f / static_cast<float>(kGridCells));
  }
}

// Table coordinate of cell edge k of a window starting at `origin` (window start minus
// the table's origin) of `size` pixels, clipped to [0, limit]. The SIMD cell coders
// repeat these operations in this order.
inline int gridEdge(float origin, float size, int k, int limit) {
  const float kf = static_cast<float>(k) * (1.f / static_cast<float>(kGridCells));
  const int e = roundHalfUp(origin + kf * size);
  return e < 0 ? 0 : (e > limit ? limit : e);
}

inline Response vec(float x, float y) {
  Response r;
  r.x = x;
  r.y = y;
  r.valid = true;
  return r;
}

// The response of kind K from the tables read at columns ix[3] and rows iy[3] (the
// feature's edges in table coordinates), with px[3], py[3] the same edges in pixels (the
// halves' sizes). Invalid when a half is empty (a window smaller than the grid, or
// clipped by the tables' border).
template <FeatureKind K, typename U, typename S>
inline Response responseAt(const ChannelTables<U, S>& t, const int ix[3], const int iy[3],
                           const int px[3], const int py[3]) {
  const int wl = px[1] - px[0], wr = px[2] - px[1];
  const int ht = py[1] - py[0], hb = py[2] - py[1];
  if (wl <= 0 || wr <= 0 || ht <= 0 || hb <= 0) return Response{};
  const int w = wl + wr, h = ht + hb;
  // Areas <= 640 x 480 < 2^24: exact in float.
  if constexpr (K == FeatureKind::Colour) {
    const float invArea = 1.f / static_cast<float>(w * h);
    const float a2 = detail::rect(t.alpha2, t.stride, ix[0], iy[0], ix[2], iy[2]);
    const float b = detail::rect(t.beta, t.stride, ix[0], iy[0], ix[2], iy[2]);
    return vec(0.5f * a2 * invArea, 0.866025404f * b * invArea);
  }
  float q[4];
  if constexpr (K == FeatureKind::Gray) {
    // mean(right) - mean(left), mean(bottom) - mean(top).
    detail::quadrants(t.gray, t.stride, ix, iy, q);
    return vec(
        (q[1] + q[3]) / static_cast<float>(wr * h) - (q[0] + q[2]) / static_cast<float>(wl * h),
        (q[2] + q[3]) / static_cast<float>(hb * w) - (q[0] + q[1]) / static_cast<float>(ht * w));
  }
  // Depth: means over valid pixels only; a half that is less than half valid is no
  // measurement, so holes (0 mm) never make a gradient.
  float n[4];
  detail::quadrants(t.depth, t.stride, ix, iy, q);
  detail::quadrants(t.count, t.stride, ix, iy, n);
  const float nl = n[0] + n[2], nr = n[1] + n[3], nt = n[0] + n[1], nb = n[2] + n[3];
  if (2.f * nl < static_cast<float>(wl * h) || 2.f * nr < static_cast<float>(wr * h) ||
      2.f * nt < static_cast<float>(ht * w) || 2.f * nb < static_cast<float>(hb * w))
    return Response{};
  const float l = q[0] + q[2], r = q[1] + q[3], tp = q[0] + q[1], bt = q[2] + q[3];
  return vec((r * nl - l * nr) / (nl * nr), (bt * nt - tp * nb) / (nt * nb));
}

// The response of a feature of kind K on the window `win` (frame px) of frame tables.
template <FeatureKind K, typename U, typename S>
inline Response evaluateKind(const Feature& f, const Box& win, const ChannelTables<U, S>& t) {
  int cx[3], cy[3];
  featureCells(f.x, f.w, cx);
  featureCells(f.y, f.h, cy);
  const float ox = win.x - static_cast<float>(t.originX);
  const float oy = win.y - static_cast<float>(t.originY);
  int px[3], py[3];
  for (int i = 0; i < 3; ++i) {
    px[i] = gridEdge(ox, win.w, cx[i], t.width);
    py[i] = gridEdge(oy, win.h, cy[i], t.height);
  }
  return responseAt<K>(t, px, py, px, py);
}

// An example patch's tables: integral tables over the grid's cells (cell (i, j) sums
// the pixels of cells [0, i) x [0, j)), and each cell edge's pixel coordinate.
struct PatchView {
  FrameTables t;                   // stride kGridCells + 1, width = height = kGridCells
  const int16_t* edgeX = nullptr;  // kGridCells + 1 pixel columns
  const int16_t* edgeY = nullptr;  // kGridCells + 1 pixel rows
};

template <FeatureKind K>
inline Response evaluateKind(const Feature& f, const PatchView& p) {
  int cx[3], cy[3];
  featureCells(f.x, f.w, cx);
  featureCells(f.y, f.h, cy);
  const int px[3] = {p.edgeX[cx[0]], p.edgeX[cx[1]], p.edgeX[cx[2]]};
  const int py[3] = {p.edgeY[cy[0]], p.edgeY[cy[1]], p.edgeY[cy[2]]};
  return responseAt<K>(p.t, cx, cy, px, py);
}

inline Response evaluate(const Feature& f, const PatchView& p) {
  switch (f.kind) {
    case FeatureKind::Gray:
      return evaluateKind<FeatureKind::Gray>(f, p);
    case FeatureKind::Depth:
      return evaluateKind<FeatureKind::Depth>(f, p);
    case FeatureKind::Colour:
      break;
  }
  return evaluateKind<FeatureKind::Colour>(f, p);
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
