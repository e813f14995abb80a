// aarch64 NEON fit kernels (FitKernels.hpp): 4 magnitude steps per instruction, the
// scalar reference's operations in its order (fastExp of FastMath.hpp written out per
// lane). aarch64 NEON arithmetic is IEEE (subnormals kept), so it is bit-exact; ARMv7
// NEON is not, and armhf uses the scalar kernels.
#include "cuetrack/core/kernels/FitKernels.hpp"
#if defined(CUETRACK_FITK_NEON)
#include <arm_neon.h>

namespace cuetrack::fitk::neon {
namespace {

inline float32x4_t fastExp4(float32x4_t v) {
  // clampf(v, -87, 87); v is never NaN here.
  v = vminq_f32(vmaxq_f32(v, vdupq_n_f32(-87.f)), vdupq_n_f32(87.f));
  // floorToInt(v * log2(e) + 0.5): truncate, then one less where that rounded up.
  const float32x4_t t = vaddq_f32(vmulq_f32(v, vdupq_n_f32(1.44269504088896f)), vdupq_n_f32(0.5f));
  int32x4_t k = vcvtq_s32_f32(t);
  k = vaddq_s32(k, vreinterpretq_s32_u32(vcgtq_f32(vcvtq_f32_s32(k), t)));
  const float32x4_t kf = vcvtq_f32_s32(k);
  const float32x4_t r = vsubq_f32(vsubq_f32(v, vmulq_f32(kf, vdupq_n_f32(0.693145751953125f))),
                                  vmulq_f32(kf, vdupq_n_f32(1.42860682030941723212e-6f)));
  float32x4_t p = vmulq_f32(r, vdupq_n_f32(0.00138888889f));
  p = vmulq_f32(r, vaddq_f32(vdupq_n_f32(0.00833333333f), p));
  p = vmulq_f32(r, vaddq_f32(vdupq_n_f32(0.0416666667f), p));
  p = vmulq_f32(r, vaddq_f32(vdupq_n_f32(0.166666667f), p));
  p = vmulq_f32(r, vaddq_f32(vdupq_n_f32(0.5f), p));
  p = vmulq_f32(r, vaddq_f32(vdupq_n_f32(1.f), p));
  p = vaddq_f32(vdupq_n_f32(1.f), p);
  const int32x4_t e = vshlq_n_s32(vaddq_s32(k, vdupq_n_s32(127)), 23);
  return vmulq_f32(p, vreinterpretq_f32_s32(e));
}

}  // namespace

void densRow(const float* lnm, float mu, float k, float norm, float* out, int n) {
  const float32x4_t vmu = vdupq_n_f32(mu), vk = vdupq_n_f32(k), vnorm = vdupq_n_f32(norm);
  for (int q = 0; q < n; q += 4) {
    const float32x4_t d = vsubq_f32(vld1q_f32(lnm + q), vmu);
    vst1q_f32(out + q, vmulq_f32(vnorm, fastExp4(vmulq_f32(vmulq_f32(vk, d), d))));
  }
}

void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0, const float* dp1,
             const float* dp2, const float* dn0, const float* dn1, const float* dn2, float eps,
             float* out, int n) {
  const float32x4_t veps = vdupq_n_f32(eps);
  for (int q = 0; q < n; q += 4) {
    const float32x4_t c = vld1q_f32(wc + q), a = vld1q_f32(wa + q), b = vld1q_f32(wb + q);
    const float32x4_t p =
        vaddq_f32(vaddq_f32(vmulq_f32(c, vld1q_f32(dp0 + q)), vmulq_f32(a, vld1q_f32(dp1 + q))),
                  vmulq_f32(b, vld1q_f32(dp2 + q)));
    const float32x4_t m =
        vaddq_f32(vaddq_f32(vmulq_f32(c, vld1q_f32(dn0 + q)), vmulq_f32(a, vld1q_f32(dn1 + q))),
                  vmulq_f32(b, vld1q_f32(dn2 + q)));
    vst1q_f32(out + q, vdivq_f32(vsubq_f32(p, m), vaddq_f32(vaddq_f32(p, m), veps)));
  }
}

}  // namespace cuetrack::fitk::neon
#endif
