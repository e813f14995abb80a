// NEON integral images, aarch64 and armv7 (same intrinsics: only ones both have).
// Per row: vld3 de-interleaves 8 RGB pixels; 16-bit prefix sums of 8 lanes by
// shift-and-add (vext with zero), widened to 32 bits, plus the running row total
// (`carry`, broadcast in every lane), plus the previous table row. Bit-exact to scalar.
// Empty without NEON (e.g. -mfpu=vfpv3-d16): the dispatcher then uses the scalar path.
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
#include <arm_neon.h>

#include "integral_rows.hpp"

namespace cuetrack::integral::neon {
namespace {

// Inclusive prefix sums across lanes: add the vector shifted up by 1, 2, 4 lanes.
inline uint16x8_t prefix16(uint16x8_t v) {
  const uint16x8_t z = vdupq_n_u16(0);
  v = vaddq_u16(v, vextq_u16(z, v, 7));
  v = vaddq_u16(v, vextq_u16(z, v, 6));
  return vaddq_u16(v, vextq_u16(z, v, 4));
}
inline uint32x4_t prefix32(uint32x4_t v) {
  const uint32x4_t z = vdupq_n_u32(0);
  v = vaddq_u32(v, vextq_u32(z, v, 3));
  return vaddq_u32(v, vextq_u32(z, v, 2));
}
inline uint32x4_t broadcastLast(uint32x4_t v) {
  return vdupq_lane_u32(vget_high_u32(v), 1);
}

// cur[0..7] = prev[0..7] + carry + (lo, hi); carry += hi's last lane. `hi` must
// already include `lo`'s total (a prefix over all 8 lanes).
inline void emit8(uint32_t* cur, const uint32_t* prev, uint32x4_t& carry, uint32x4_t lo,
                  uint32x4_t hi) {
  vst1q_u32(cur, vaddq_u32(vaddq_u32(lo, carry), vld1q_u32(prev)));
  vst1q_u32(cur + 4, vaddq_u32(vaddq_u32(hi, carry), vld1q_u32(prev + 4)));
  carry = vaddq_u32(carry, broadcastLast(hi));
}
// From an unsigned 16-bit prefix over 8 lanes.
inline void emit8u(uint32_t* cur, const uint32_t* prev, uint32x4_t& carry, uint16x8_t p) {
  emit8(cur, prev, carry, vmovl_u16(vget_low_u16(p)), vmovl_u16(vget_high_u16(p)));
}
// From a signed 16-bit prefix over 8 lanes (sign-extended; the tables wrap like int32).
inline void emit8s(int32_t* cur, const int32_t* prev, uint32x4_t& carry, uint16x8_t p) {
  const int16x8_t s = vreinterpretq_s16_u16(p);
  emit8(reinterpret_cast<uint32_t*>(cur), reinterpret_cast<const uint32_t*>(prev), carry,
        vreinterpretq_u32_s32(vmovl_s16(vget_low_s16(s))),
        vreinterpretq_u32_s32(vmovl_s16(vget_high_s16(s))));
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
    uint32x4_t carryG = vdupq_n_u32(0), carryA = carryG, carryB = carryG;
    int x = 0;
    for (; x + 8 <= width; x += 8) {
      const uint8x8x3_t px = vld3_u8(reinterpret_cast<const uint8_t*>(s + x));
      const uint8x8_t r = px.val[0], g = px.val[1], b = px.val[2];
      // 77 R + 150 G + 29 B + 128 <= 65,408: fits 16 bits; vrshr adds the 128.
      uint16x8_t wsum = vmull_u8(r, vdup_n_u8(77));
      wsum = vmlal_u8(wsum, g, vdup_n_u8(150));
      wsum = vmlal_u8(wsum, b, vdup_n_u8(29));
      const uint16x8_t grayPx = vrshrq_n_u16(wsum, 8);
      // (R-G) + (R-B) and G-B in modular 16 bits are the signed values exactly.
      const uint16x8_t alphaPx = vaddq_u16(vsubl_u8(r, g), vsubl_u8(r, b));
      const uint16x8_t betaPx = vsubl_u8(g, b);
      // Over 8 lanes: gray <= 2,040, |alpha2| <= 4,080, |beta| <= 2,040: 16 bits hold them.
      const std::ptrdiff_t p = prev + x, c = cur + x;
      emit8u(gray + c, gray + p, carryG, prefix16(grayPx));
      emit8s(alpha2 + c, alpha2 + p, carryA, prefix16(alphaPx));
      emit8s(beta + c, beta + p, carryB, prefix16(betaPx));
    }
    rows::rgbTail(s, x, width, gray + prev, gray + cur, alpha2 + prev, alpha2 + cur, beta + prev,
                  beta + cur, vgetq_lane_u32(carryG, 0),
                  static_cast<int32_t>(vgetq_lane_u32(carryA, 0)),
                  static_cast<int32_t>(vgetq_lane_u32(carryB, 0)));
  }
}

void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  rows::clearTopRow(sumMm, width);
  rows::clearTopRow(count, width);
  const uint16x8_t maxMm = vdupq_n_u16(kMaxDepthMm);
  for (int y = 0; y < height; ++y) {
    const uint16_t* s = srcMm + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sumMm[cur - 1] = 0;
    count[cur - 1] = 0;
    uint32x4_t carryD = vdupq_n_u32(0), carryC = carryD;
    int x = 0;
    for (; x + 8 <= width; x += 8) {
      const uint16x8_t d = vld1q_u16(s + x);
      const uint16x8_t valid = vandq_u16(vtstq_u16(d, d), vcleq_u16(d, maxMm));
      const uint16x8_t dv = vandq_u16(d, valid);
      // Depth sums reach 80,000 within 8 lanes: widen before the prefix sum.
      const uint32x4_t lo = prefix32(vmovl_u16(vget_low_u16(dv)));
      const uint32x4_t hi = vaddq_u32(prefix32(vmovl_u16(vget_high_u16(dv))), broadcastLast(lo));
      const std::ptrdiff_t p = prev + x, c = cur + x;
      emit8(sumMm + c, sumMm + p, carryD, lo, hi);
      emit8u(count + c, count + p, carryC, prefix16(vshrq_n_u16(valid, 15)));
    }
    rows::depthTail(s, x, width, sumMm + prev, sumMm + cur, count + prev, count + cur,
                    vgetq_lane_u32(carryD, 0), vgetq_lane_u32(carryC, 0));
  }
}

void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  rows::clearTopRow(sum, width);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + rows::offset(y, srcStride);
    const std::ptrdiff_t prev = rows::offset(y, sumStride) + 1, cur = prev + sumStride;
    sum[cur - 1] = 0;
    uint32x4_t carry = vdupq_n_u32(0);
    int x = 0;
    for (; x + 16 <= width; x += 16) {
      const uint8x16_t v = vld1q_u8(s + x);
      // 8 x 255 = 2,040: 16-bit prefix sums of 8 pixels cannot wrap.
      const uint16x8_t lo = prefix16(vmovl_u8(vget_low_u8(v)));
      const uint16x8_t hi = prefix16(vmovl_u8(vget_high_u8(v)));
      emit8u(sum + cur + x, sum + prev + x, carry, lo);
      emit8u(sum + cur + x + 8, sum + prev + x + 8, carry, hi);
    }
    rows::grayTail(s, x, width, sum + prev, sum + cur, vgetq_lane_u32(carry, 0));
  }
}

}  // namespace cuetrack::integral::neon
#endif
