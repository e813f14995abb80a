// Scalar reference integral images: every SIMD path must match these bit for bit.
#include "integral_rows.hpp"

// core is built with -fno-exceptions -fno-rtti in every preset; fail the build if not.
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(__GXX_RTTI) || defined(__cpp_rtti)
#error "cuetrack_core must be compiled with -fno-exceptions -fno-rtti"
#endif

namespace cuetrack::integral::scalar {

void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2,
         int32_t* beta, int sumStride) {
  rows::clearTopRow(gray, width);
  rows::clearTopRow(alpha2, width);
  rows::clearTopRow(beta, width);
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    gray[cur - 1] = 0;
    alpha2[cur - 1] = 0;
    beta[cur - 1] = 0;
    rows::rgbTail(src + rows::offset(y, srcStride), 0, width, gray + prev, gray + cur,
                  alpha2 + prev, alpha2 + cur, beta + prev, beta + cur, 0, 0, 0);
  }
}

void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  rows::clearTopRow(sumMm, width);
  rows::clearTopRow(count, width);
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sumMm[cur - 1] = 0;
    count[cur - 1] = 0;
    rows::depthTail(srcMm + rows::offset(y, srcStride), 0, width, sumMm + prev, sumMm + cur,
                    count + prev, count + cur, 0, 0);
  }
}

void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  rows::clearTopRow(sum, width);
  for (int y = 0; y < height; ++y) {
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sum[cur - 1] = 0;
    rows::grayTail(src + rows::offset(y, srcStride), 0, width, sum + prev, sum + cur, 0);
  }
}

}  // namespace cuetrack::integral::scalar
