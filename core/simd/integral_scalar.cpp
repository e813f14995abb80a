// Scalar reference integral images: every SIMD path must match these bit for bit.
#include "cuetrack/core/Integral.hpp"

#include <cstring>

namespace cuetrack::integral::scalar {

void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2,
         int32_t* beta, int sumStride) {
  std::memset(gray, 0, sizeof(uint32_t) * static_cast<std::size_t>(width + 1));
  std::memset(alpha2, 0, sizeof(int32_t) * static_cast<std::size_t>(width + 1));
  std::memset(beta, 0, sizeof(int32_t) * static_cast<std::size_t>(width + 1));
  for (int y = 0; y < height; ++y) {
    const Rgb8* s = src + static_cast<std::ptrdiff_t>(y) * srcStride;
    const std::ptrdiff_t prev = static_cast<std::ptrdiff_t>(y) * sumStride;
    const std::ptrdiff_t cur = prev + sumStride;
    gray[cur] = 0;
    alpha2[cur] = 0;
    beta[cur] = 0;
    uint32_t rowGray = 0;
    int32_t rowAlpha = 0, rowBeta = 0;
    for (int x = 0; x < width; ++x) {
      const int r = s[x].r, g = s[x].g, b = s[x].b;
      rowGray += static_cast<uint32_t>((77 * r + 150 * g + 29 * b + 128) >> 8);
      rowAlpha += 2 * r - g - b;
      rowBeta += g - b;
      gray[cur + x + 1] = gray[prev + x + 1] + rowGray;
      alpha2[cur + x + 1] = alpha2[prev + x + 1] + rowAlpha;
      beta[cur + x + 1] = beta[prev + x + 1] + rowBeta;
    }
  }
}

void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  std::memset(sumMm, 0, sizeof(uint32_t) * static_cast<std::size_t>(width + 1));
  std::memset(count, 0, sizeof(uint32_t) * static_cast<std::size_t>(width + 1));
  for (int y = 0; y < height; ++y) {
    const uint16_t* s = srcMm + static_cast<std::ptrdiff_t>(y) * srcStride;
    const std::ptrdiff_t prev = static_cast<std::ptrdiff_t>(y) * sumStride;
    const std::ptrdiff_t cur = prev + sumStride;
    sumMm[cur] = 0;
    count[cur] = 0;
    uint32_t rowSum = 0, rowCount = 0;
    for (int x = 0; x < width; ++x) {
      const uint32_t d = s[x];
      const bool valid = d != 0 && d <= kMaxDepthMm;
      rowSum += valid ? d : 0u;
      rowCount += valid ? 1u : 0u;
      sumMm[cur + x + 1] = sumMm[prev + x + 1] + rowSum;
      count[cur + x + 1] = count[prev + x + 1] + rowCount;
    }
  }
}

void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  std::memset(sum, 0, sizeof(uint32_t) * static_cast<std::size_t>(width + 1));
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + static_cast<std::ptrdiff_t>(y) * srcStride;
    const std::ptrdiff_t prev = static_cast<std::ptrdiff_t>(y) * sumStride;
    const std::ptrdiff_t cur = prev + sumStride;
    sum[cur] = 0;
    uint32_t rowSum = 0;
    for (int x = 0; x < width; ++x) {
      rowSum += s[x];
      sum[cur + x + 1] = sum[prev + x + 1] + rowSum;
    }
  }
}

}  // namespace cuetrack::integral::scalar
