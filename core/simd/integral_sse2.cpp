// SSE2 integral images (baseline on x86-64). Per row: a prefix sum of 4 or 8
// lanes in registers (shift-and-add), plus the running row total (`carry`, kept
// broadcast in every lane), plus the previous table row. Bit-exact to scalar.
#include <emmintrin.h>

#include "integral_rows.hpp"

namespace cuetrack::integral::sse2 {
namespace {

inline __m128i load(const void* p) {
  return _mm_loadu_si128(static_cast<const __m128i*>(p));
}

// Inclusive prefix sums across lanes.
inline __m128i prefix32(__m128i v) {
  v = _mm_add_epi32(v, _mm_slli_si128(v, 4));
  return _mm_add_epi32(v, _mm_slli_si128(v, 8));
}
inline __m128i prefix16(__m128i v) {
  v = _mm_add_epi16(v, _mm_slli_si128(v, 2));
  v = _mm_add_epi16(v, _mm_slli_si128(v, 4));
  return _mm_add_epi16(v, _mm_slli_si128(v, 8));
}

// cur[0..3] = prev[0..3] + carry + prefix; carry += the 4 lanes' total. The carry
// chain is one add per 4 cells; the broadcast of the total stays off it.
inline void emit4(void* cur, const void* prev, __m128i& carry, __m128i prefix) {
  _mm_storeu_si128(static_cast<__m128i*>(cur),
                   _mm_add_epi32(_mm_add_epi32(prefix, carry), load(prev)));
  carry = _mm_add_epi32(carry, _mm_shuffle_epi32(prefix, 0xFF));
}

// Same for 8 cells from an unsigned 16-bit prefix over 8 lanes (lanes 4..7 already
// include lanes 0..3, so both halves take the same carry).
inline void emit8(void* cur, const void* prev, __m128i& carry, __m128i prefix16Lanes) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i lo = _mm_unpacklo_epi16(prefix16Lanes, zero);
  const __m128i hi = _mm_unpackhi_epi16(prefix16Lanes, zero);
  uint32_t* out = static_cast<uint32_t*>(cur);
  const uint32_t* in = static_cast<const uint32_t*>(prev);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out),
                   _mm_add_epi32(_mm_add_epi32(lo, carry), load(in)));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 4),
                   _mm_add_epi32(_mm_add_epi32(hi, carry), load(in + 4)));
  carry = _mm_add_epi32(carry, _mm_shuffle_epi32(hi, 0xFF));
}

inline uint32_t lane0(__m128i v) {
  return static_cast<uint32_t>(_mm_cvtsi128_si32(v));
}

// 4 packed RGB888 pixels (bytes 0..11 of v) -> one pixel per 32-bit lane (0x00BBGGRR).
inline __m128i spreadPixels(__m128i v) {
  const __m128i m0 = _mm_set_epi32(0, 0, 0, 0x00FFFFFF);
  const __m128i m1 = _mm_set_epi32(0, 0, 0x00FFFFFF, 0);
  const __m128i m2 = _mm_set_epi32(0, 0x00FFFFFF, 0, 0);
  const __m128i m3 = _mm_set_epi32(0x00FFFFFF, 0, 0, 0);
  const __m128i a = _mm_or_si128(_mm_and_si128(v, m0), _mm_and_si128(_mm_slli_si128(v, 1), m1));
  const __m128i b = _mm_or_si128(_mm_and_si128(_mm_slli_si128(v, 2), m2),
                                 _mm_and_si128(_mm_slli_si128(v, 3), m3));
  return _mm_or_si128(a, b);
}

struct Channels {
  __m128i gray, alpha2, beta;
};

// Per-pixel values in 32-bit lanes, in integers exactly as the scalar reference:
// pmaddwd on the (R, B) 16-bit halves gives the weighted R and B terms at once.
inline Channels channels(__m128i px) {
  const __m128i rb = _mm_and_si128(px, _mm_set1_epi32(0x00FF00FF));
  const __m128i g = _mm_and_si128(_mm_srli_epi32(px, 8), _mm_set1_epi32(0xFF));
  const __m128i grayWeighted = _mm_add_epi32(_mm_madd_epi16(rb, _mm_set1_epi32(77 | (29 << 16))),
                                             _mm_madd_epi16(g, _mm_set1_epi32(150)));
  Channels c;
  c.gray = _mm_srli_epi32(_mm_add_epi32(grayWeighted, _mm_set1_epi32(128)), 8);
  // (2, -1) on (R, B) then -G; (0, -1) on (R, B) then +G.
  c.alpha2 = _mm_sub_epi32(_mm_madd_epi16(rb, _mm_set1_epi32(static_cast<int>(0xFFFF0002u))), g);
  c.beta = _mm_add_epi32(_mm_madd_epi16(rb, _mm_set1_epi32(static_cast<int>(0xFFFF0000u))), g);
  return c;
}

}  // namespace

void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* gray, int32_t* alpha2,
         int32_t* beta, int sumStride) {
  rows::clearTopRow(gray, width);
  rows::clearTopRow(alpha2, width);
  rows::clearTopRow(beta, width);
  for (int y = 0; y < height; ++y) {
    const Rgb8* s = src + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    gray[cur - 1] = 0;
    alpha2[cur - 1] = 0;
    beta[cur - 1] = 0;
    __m128i carryG = _mm_setzero_si128(), carryA = carryG, carryB = carryG;
    int x = 0;
    // 8 pixels = 24 bytes per step, read exactly (16 + 8 bytes), so no over-read.
    for (; x + 8 <= width; x += 8) {
      const uint8_t* bytes = reinterpret_cast<const uint8_t*>(s + x);
      const __m128i v0 = load(bytes);
      const __m128i v1 = _mm_or_si128(
          _mm_srli_si128(v0, 12),
          _mm_slli_si128(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bytes + 16)), 4));
      const Channels lo = channels(spreadPixels(v0));
      const Channels hi = channels(spreadPixels(v1));
      const std::ptrdiff_t p = prev + x, c = cur + x;
      emit4(gray + c, gray + p, carryG, prefix32(lo.gray));
      emit4(gray + c + 4, gray + p + 4, carryG, prefix32(hi.gray));
      emit4(alpha2 + c, alpha2 + p, carryA, prefix32(lo.alpha2));
      emit4(alpha2 + c + 4, alpha2 + p + 4, carryA, prefix32(hi.alpha2));
      emit4(beta + c, beta + p, carryB, prefix32(lo.beta));
      emit4(beta + c + 4, beta + p + 4, carryB, prefix32(hi.beta));
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
    __m128i carryD = zero, carryC = zero;
    int x = 0;
    for (; x + 8 <= width; x += 8) {
      const __m128i d = load(s + x);
      // Unsigned d <= max as (d -sat max) == 0; SSE2 has no unsigned 16-bit compare.
      const __m128i valid = _mm_andnot_si128(_mm_cmpeq_epi16(d, zero),
                                             _mm_cmpeq_epi16(_mm_subs_epu16(d, maxMm), zero));
      const __m128i dv = _mm_and_si128(d, valid);
      const __m128i n = prefix16(_mm_srli_epi16(valid, 15));  // <= 8: fits 16 bits
      const std::ptrdiff_t p = prev + x, c = cur + x;
      // Depth sums reach 80,000 within 8 lanes: widen before the prefix sum.
      emit4(sumMm + c, sumMm + p, carryD, prefix32(_mm_unpacklo_epi16(dv, zero)));
      emit4(sumMm + c + 4, sumMm + p + 4, carryD, prefix32(_mm_unpackhi_epi16(dv, zero)));
      emit8(count + c, count + p, carryC, n);
    }
    rows::depthTail(s, x, width, sumMm + prev, sumMm + cur, count + prev, count + cur,
                    lane0(carryD), lane0(carryC));
  }
}

void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  rows::clearTopRow(sum, width);
  const __m128i zero = _mm_setzero_si128();
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sum[cur - 1] = 0;
    __m128i carry = zero;
    int x = 0;
    for (; x + 16 <= width; x += 16) {
      const __m128i v = load(s + x);
      // 8 x 255 = 2040: 16-bit prefix sums of 8 pixels cannot wrap.
      const __m128i lo = prefix16(_mm_unpacklo_epi8(v, zero));
      const __m128i hi = prefix16(_mm_unpackhi_epi8(v, zero));
      const std::ptrdiff_t p = prev + x, c = cur + x;
      emit8(sum + c, sum + p, carry, lo);
      emit8(sum + c + 8, sum + p + 8, carry, hi);
    }
    rows::grayTail(s, x, width, sum + prev, sum + cur, lane0(carry));
  }
}

}  // namespace cuetrack::integral::sse2
