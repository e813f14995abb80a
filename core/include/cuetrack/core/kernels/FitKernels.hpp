// The inner loops of WeakClassifier::fit over the kLutMags magnitude steps of one row:
// a fitted lognormal's density at each step, and the baked GentleBoost value of each
// table cell. Every step is independent, so the SIMD versions compute 4 steps per
// instruction with exactly the scalar operations in the scalar order: bit-exact
// (tests/simd/test_simd_fit). `scalar` is the reference.
//   densRow  out[q] = norm * fastExp((k * d) * d), d = lnm[q] - mu
//   bakeRow  out[q] = (p - m) / ((p + m) + eps),
//            p = (wc[q] dp0[q] + wa[q] dp1[q]) + wb[q] dp2[q], m likewise with dn0..dn2
// n must be a multiple of 4.
#pragma once

namespace cuetrack::fitk {

#define CUETRACK_FITK_DECLARE_ISA(ns)                                                  \
  namespace ns {                                                                       \
  void densRow(const float* lnm, float mu, float k, float norm, float* out, int n);    \
  void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0,    \
               const float* dp1, const float* dp2, const float* dn0, const float* dn1, \
               const float* dn2, float eps, float* out, int n);                        \
  }

CUETRACK_FITK_DECLARE_ISA(scalar)
#if defined(__x86_64__) || defined(__SSE2__)
#define CUETRACK_FITK_SSE2 1
CUETRACK_FITK_DECLARE_ISA(sse2)
#endif
// aarch64 only: ARMv7 NEON flushes subnormals to zero, so it is not bit-exact to VFP.
#if defined(__aarch64__) && defined(__ARM_NEON)
#define CUETRACK_FITK_NEON 1
CUETRACK_FITK_DECLARE_ISA(neon)
#endif
#undef CUETRACK_FITK_DECLARE_ISA

// The implementation this build uses (SSE2 on x86-64, NEON on aarch64, else scalar).
void densRow(const float* lnm, float mu, float k, float norm, float* out, int n);
void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0, const float* dp1,
             const float* dp2, const float* dn0, const float* dn1, const float* dn2, float eps,
             float* out, int n);
const char* activeIsa();

}  // namespace cuetrack::fitk
