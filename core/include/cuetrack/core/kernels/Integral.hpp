// Integral images (summed-area tables), the base of every feature.
//
// Layout: a table for a w x h image has (w+1) x (h+1) cells, row 0 and column 0
// are zero, and cell (x, y) holds the sum of src over [0, x) x [0, y). Any
// rectangle's sum is then four reads (rectSum). Callers own every buffer.
//
// Channels and overflow (all integer, so SIMD paths are bit-exact to scalar):
//   gray   uint32  gray = (77 R + 150 G + 29 B + 128) >> 8 in [0, 255];
//                  max total 640*480*255 = 78,336,000 < 2^32: no wrap at all.
//   alpha2 int32   2 alpha = 2R - G - B in [-510, 510] (the paper's alpha = value / 2);
//                  |total| <= 640*480*510 = 156,672,000 < 2^31.
//   beta   int32   G - B in [-255, 255] (the paper's beta = value * sqrt(3)/2);
//                  |total| <= 78,336,000 < 2^31.
//   depth  uint32  depth [mm], values 0 or > kMaxDepthMm count as missing (add 0);
//                  max total 640*480*10,000 = 3,072,000,000 < 2^32: no wrap.
//   count  uint32  number of valid depth pixels, so holes never bias averages.
// Largest image each accumulator holds without wrap: gray 16.8 Mpx, alpha2 4.2 Mpx,
// beta 8.4 Mpx, depth (at 10 m) 429 kpx; kMaxPixels is 307,200.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Image.hpp"

namespace cuetrack::integral {

// One implementation per instruction set, same signatures; `scalar` is the reference.
#define CUETRACK_INTEGRAL_DECLARE_ISA(ns)                                                          \
  namespace ns {                                                                                   \
  void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2, \
           int32_t* beta, int sumStride);                                                          \
  void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,         \
             uint32_t* count, int sumStride);                                                      \
  void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum,               \
            int sumStride);                                                                        \
  }

CUETRACK_INTEGRAL_DECLARE_ISA(scalar)
#if defined(__x86_64__) || defined(__i386__)
CUETRACK_INTEGRAL_DECLARE_ISA(sse2)
CUETRACK_INTEGRAL_DECLARE_ISA(avx2)
#endif
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
CUETRACK_INTEGRAL_DECLARE_ISA(neon)
#endif
#undef CUETRACK_INTEGRAL_DECLARE_ISA

// The fastest implementation this CPU runs (static on ARM, runtime check for AVX2 on x86).
void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2,
         int32_t* beta, int sumStride);
void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride);
void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride);
// Name of the implementations the dispatchers above use ("avx2+sse2": AVX2 for rgb, SSE2
// for depth and gray; "sse2", "neon", "scalar").
const char* activeIsa();
bool avx2Available();

// Sum over [x0, x1) x [y0, y1) of the image behind table `t` (unsigned: modular
// arithmetic is exact while the true sum fits, see above).
template <typename T>
inline T rectSum(const T* t, int stride, int x0, int y0, int x1, int y1) {
  const T* r0 = t + static_cast<std::ptrdiff_t>(y0) * stride;
  const T* r1 = t + static_cast<std::ptrdiff_t>(y1) * stride;
  return static_cast<T>(r1[x1] - r1[x0] - r0[x1] + r0[x0]);
}

}  // namespace cuetrack::integral
