// AVX2 integral images (compiled with -mavx2 for this file only; called only after
// the runtime check in integral_dispatch.cpp). Same scheme as SSE2 with 8 lanes:
// an in-lane prefix sum, then the low 128-bit half's total added to the high half.
#include <immintrin.h>

#include "integral_rows.hpp"

namespace cuetrack::integral::avx2 {
namespace {

inline __m256i load8x32(const void* p) {
  return _mm256_loadu_si256(static_cast<const __m256i*>(p));
}
inline __m128i load128(const void* p) {
  return _mm_loadu_si128(static_cast<const __m128i*>(p));
}

// Inclusive prefix sum over 8 32-bit lanes.
inline __m256i prefix32(__m256i v) {
  v = _mm256_add_epi32(v, _mm256_slli_si256(v, 4));
  v = _mm256_add_epi32(v, _mm256_slli_si256(v, 8));
  // [0, low half] then lane 3 of it broadcast: the low half's total into the high half.
  const __m256i low = _mm256_permute2x128_si256(v, v, 0x08);
  return _mm256_add_epi32(v, _mm256_shuffle_epi32(low, 0xFF));
}

// cur[0..7] = prev[0..7] + carry + prefix; carry += the 8 lanes' total.
inline void emit8(void* cur, const void* prev, __m256i& carry, __m256i prefix) {
  _mm256_storeu_si256(static_cast<__m256i*>(cur),
                      _mm256_add_epi32(_mm256_add_epi32(prefix, carry), load8x32(prev)));
  carry = _mm256_add_epi32(carry, _mm256_permutevar8x32_epi32(prefix, _mm256_set1_epi32(7)));
}

inline uint32_t lane0(__m256i v) {
  return static_cast<uint32_t>(_mm256_cvtsi256_si32(v));
}

struct Channels {
  __m256i gray, alpha2, beta;
};

// 8 pixels, one per 32-bit lane (0x00BBGGRR) -> the channel values, in integers
// exactly as the scalar reference (pmaddwd on the (R, B) 16-bit halves).
inline Channels channels(__m256i px) {
  const __m256i rb = _mm256_and_si256(px, _mm256_set1_epi32(0x00FF00FF));
  const __m256i g = _mm256_and_si256(_mm256_srli_epi32(px, 8), _mm256_set1_epi32(0xFF));
  const __m256i grayWeighted =
      _mm256_add_epi32(_mm256_madd_epi16(rb, _mm256_set1_epi32(77 | (29 << 16))),
                       _mm256_madd_epi16(g, _mm256_set1_epi32(150)));
  Channels c;
  c.gray = _mm256_srli_epi32(_mm256_add_epi32(grayWeighted, _mm256_set1_epi32(128)), 8);
  c.alpha2 =
      _mm256_sub_epi32(_mm256_madd_epi16(rb, _mm256_set1_epi32(static_cast<int>(0xFFFF0002u))), g);
  c.beta =
      _mm256_add_epi32(_mm256_madd_epi16(rb, _mm256_set1_epi32(static_cast<int>(0xFFFF0000u))), g);
  return c;
}

}  // namespace

void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2,
         int32_t* beta, int sumStride) {
  rows::clearTopRow(gray, width);
  rows::clearTopRow(alpha2, width);
  rows::clearTopRow(beta, width);
  // Bytes 3i..3i+2 of each 128-bit half -> 32-bit lane i, top byte zero.
  const __m256i spread = _mm256_setr_epi8(0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1, 9, 10, 11, -1,  //
                                          0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1, 9, 10, 11, -1);
  for (int y = 0; y < height; ++y) {
    const Rgb8* s = src + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    gray[cur - 1] = 0;
    alpha2[cur - 1] = 0;
    beta[cur - 1] = 0;
    __m256i carryG = _mm256_setzero_si256(), carryA = carryG, carryB = carryG;
    int x = 0;
    // 8 pixels = 24 bytes per step, read exactly (16 + 8 bytes), so no over-read.
    for (; x + 8 <= width; x += 8) {
      const uint8_t* bytes = reinterpret_cast<const uint8_t*>(s + x);
      const __m128i v0 = load128(bytes);
      const __m128i v1 = _mm_or_si128(
          _mm_srli_si128(v0, 12),
          _mm_slli_si128(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bytes + 16)), 4));
      const Channels ch = channels(
          _mm256_shuffle_epi8(_mm256_inserti128_si256(_mm256_castsi128_si256(v0), v1, 1), spread));
      emit8(gray + cur + x, gray + prev + x, carryG, prefix32(ch.gray));
      emit8(alpha2 + cur + x, alpha2 + prev + x, carryA, prefix32(ch.alpha2));
      emit8(beta + cur + x, beta + prev + x, carryB, prefix32(ch.beta));
    }
    rows::rgbTail(s, x, width, gray + prev, gray + cur, alpha2 + prev, alpha2 + cur, beta + prev,
                  beta + cur, lane0(carryG), static_cast<int32_t>(lane0(carryA)),
                  static_cast<int32_t>(lane0(carryB)));
  }
}

void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  rows::clearTopRow(sumMm, width);
  rows::clearTopRow(count, width);
  const __m128i zero = _mm_setzero_si128();
  const __m128i maxMm = _mm_set1_epi16(static_cast<short>(kMaxDepthMm));
  for (int y = 0; y < height; ++y) {
    const uint16_t* s = srcMm + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sumMm[cur - 1] = 0;
    count[cur - 1] = 0;
    __m256i carryD = _mm256_setzero_si256(), carryC = carryD;
    int x = 0;
    for (; x + 8 <= width; x += 8) {
      const __m128i d = load128(s + x);
      // Unsigned 16-bit d <= max: min(d, max) == d.
      const __m128i valid =
          _mm_andnot_si128(_mm_cmpeq_epi16(d, zero), _mm_cmpeq_epi16(_mm_min_epu16(d, maxMm), d));
      const __m256i dv = _mm256_cvtepu16_epi32(_mm_and_si128(d, valid));
      const __m256i n = _mm256_cvtepu16_epi32(_mm_srli_epi16(valid, 15));
      emit8(sumMm + cur + x, sumMm + prev + x, carryD, prefix32(dv));
      emit8(count + cur + x, count + prev + x, carryC, prefix32(n));
    }
    rows::depthTail(s, x, width, sumMm + prev, sumMm + cur, count + prev, count + cur,
                    lane0(carryD), lane0(carryC));
  }
}

void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  rows::clearTopRow(sum, width);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sum[cur - 1] = 0;
    __m256i carry = _mm256_setzero_si256();
    int x = 0;
    for (; x + 16 <= width; x += 16) {
      const __m128i v = load128(s + x);
      const __m256i lo = _mm256_cvtepu8_epi32(v);
      const __m256i hi = _mm256_cvtepu8_epi32(_mm_srli_si128(v, 8));
      emit8(sum + cur + x, sum + prev + x, carry, prefix32(lo));
      emit8(sum + cur + x + 8, sum + prev + x + 8, carry, prefix32(hi));
    }
    rows::grayTail(s, x, width, sum + prev, sum + cur, lane0(carry));
  }
}

}  // namespace cuetrack::integral::avx2
