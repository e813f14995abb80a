// Private to core/simd: the per-row scalar recurrences shared by the reference
// and the SIMD kernels' tails, so every path computes each cell the same way.
// `prev` and `cur` point at the table cell of pixel 0 (column 1) of the previous
// and current table rows; `row*` is the running sum of this image row so far.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "cuetrack/core/kernels/Integral.hpp"

namespace cuetrack::integral::rows {

inline std::ptrdiff_t offset(int y, int stride) {
  return static_cast<std::ptrdiff_t>(y) * stride;
}

// Row 0 of a (width+1)-wide table is all zeros.
template <typename T>
inline void clearTopRow(T* table, int width) {
  std::memset(table, 0, sizeof(T) * static_cast<std::size_t>(width + 1));
}

inline void rgbTail(const Rgb8* s, int x, int width, const uint32_t* prevG, uint32_t* curG,
                    const int32_t* prevA, int32_t* curA, const int32_t* prevB, int32_t* curB,
                    uint32_t rowG, int32_t rowA, int32_t rowB) {
  for (; x < width; ++x) {
    const int r = s[x].r, g = s[x].g, b = s[x].b;
    rowG += static_cast<uint32_t>((77 * r + 150 * g + 29 * b + 128) >> 8);
    rowA += 2 * r - g - b;
    rowB += g - b;
    curG[x] = prevG[x] + rowG;
    curA[x] = prevA[x] + rowA;
    curB[x] = prevB[x] + rowB;
  }
}

inline void depthTail(const uint16_t* s, int x, int width, const uint32_t* prevD, uint32_t* curD,
                      const uint32_t* prevC, uint32_t* curC, uint32_t rowD, uint32_t rowC) {
  for (; x < width; ++x) {
    const uint32_t d = s[x];
    const bool valid = d != 0 && d <= kMaxDepthMm;
    rowD += valid ? d : 0u;
    rowC += valid ? 1u : 0u;
    curD[x] = prevD[x] + rowD;
    curC[x] = prevC[x] + rowC;
  }
}

inline void grayTail(const uint8_t* s, int x, int width, const uint32_t* prev, uint32_t* cur,
                     uint32_t row) {
  for (; x < width; ++x) {
    row += s[x];
    cur[x] = prev[x] + row;
  }
}

}  // namespace cuetrack::integral::rows
