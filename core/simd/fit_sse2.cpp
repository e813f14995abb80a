// SSE2 fit kernels (FitKernels.hpp): 4 magnitude steps per instruction, the scalar
// reference's operations in its order (fastExp of FastMath.hpp written out per lane).
#include "cuetrack/core/kernels/FitKernels.hpp"
#if defined(CUETRACK_FITK_SSE2)
#include <emmintrin.h>

namespace cuetrack::fitk::sse2 {
namespace {

inline __m128 fastExp4(__m128 v) {
  // clampf(v, -87, 87) = v < lo ? lo : (v > hi ? hi : v): maxps(a, b) is a > b ? a : b.
  v = _mm_max_ps(_mm_set1_ps(-87.f), _mm_min_ps(_mm_set1_ps(87.f), v));
  // floorToInt(v * log2(e) + 0.5): truncate, then one less where that rounded up.
  const __m128 t = _mm_add_ps(_mm_mul_ps(v, _mm_set1_ps(1.44269504088896f)), _mm_set1_ps(0.5f));
  __m128i k = _mm_cvttps_epi32(t);
  k = _mm_add_epi32(k, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(k), t)));
  const __m128 kf = _mm_cvtepi32_ps(k);
  const __m128 r = _mm_sub_ps(_mm_sub_ps(v, _mm_mul_ps(kf, _mm_set1_ps(0.693145751953125f))),
                              _mm_mul_ps(kf, _mm_set1_ps(1.42860682030941723212e-6f)));
  __m128 p = _mm_mul_ps(r, _mm_set1_ps(0.00138888889f));
  p = _mm_mul_ps(r, _mm_add_ps(_mm_set1_ps(0.00833333333f), p));
  p = _mm_mul_ps(r, _mm_add_ps(_mm_set1_ps(0.0416666667f), p));
  p = _mm_mul_ps(r, _mm_add_ps(_mm_set1_ps(0.166666667f), p));
  p = _mm_mul_ps(r, _mm_add_ps(_mm_set1_ps(0.5f), p));
  p = _mm_mul_ps(r, _mm_add_ps(_mm_set1_ps(1.f), p));
  p = _mm_add_ps(_mm_set1_ps(1.f), p);
  const __m128i e = _mm_slli_epi32(_mm_add_epi32(k, _mm_set1_epi32(127)), 23);
  return _mm_mul_ps(p, _mm_castsi128_ps(e));
}

}  // namespace

void densRow(const float* lnm, float mu, float k, float norm, float* out, int n) {
  const __m128 vmu = _mm_set1_ps(mu), vk = _mm_set1_ps(k), vnorm = _mm_set1_ps(norm);
  for (int q = 0; q < n; q += 4) {
    const __m128 d = _mm_sub_ps(_mm_loadu_ps(lnm + q), vmu);
    _mm_storeu_ps(out + q, _mm_mul_ps(vnorm, fastExp4(_mm_mul_ps(_mm_mul_ps(vk, d), d))));
  }
}

void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0, const float* dp1,
             const float* dp2, const float* dn0, const float* dn1, const float* dn2, float eps,
             float* out, int n) {
  const __m128 veps = _mm_set1_ps(eps);
  for (int q = 0; q < n; q += 4) {
    const __m128 c = _mm_loadu_ps(wc + q), a = _mm_loadu_ps(wa + q), b = _mm_loadu_ps(wb + q);
    const __m128 p = _mm_add_ps(
        _mm_add_ps(_mm_mul_ps(c, _mm_loadu_ps(dp0 + q)), _mm_mul_ps(a, _mm_loadu_ps(dp1 + q))),
        _mm_mul_ps(b, _mm_loadu_ps(dp2 + q)));
    const __m128 m = _mm_add_ps(
        _mm_add_ps(_mm_mul_ps(c, _mm_loadu_ps(dn0 + q)), _mm_mul_ps(a, _mm_loadu_ps(dn1 + q))),
        _mm_mul_ps(b, _mm_loadu_ps(dn2 + q)));
    _mm_storeu_ps(out + q, _mm_div_ps(_mm_sub_ps(p, m), _mm_add_ps(_mm_add_ps(p, m), veps)));
  }
}

}  // namespace cuetrack::fitk::sse2
#endif
