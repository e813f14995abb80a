// Scalar reference of the fit kernels (FitKernels.hpp): WeakClassifier::fit's loops.
#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/kernels/FitKernels.hpp"

namespace cuetrack::fitk::scalar {

void densRow(const float* lnm, float mu, float k, float norm, float* out, int n) {
  for (int q = 0; q < n; ++q) {
    const float d = lnm[q] - mu;
    out[q] = norm * fmath::fastExp(k * d * d);
  }
}

void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0, const float* dp1,
             const float* dp2, const float* dn0, const float* dn1, const float* dn2, float eps,
             float* out, int n) {
  for (int q = 0; q < n; ++q) {
    const float p = wc[q] * dp0[q] + wa[q] * dp1[q] + wb[q] * dp2[q];
    const float m = wc[q] * dn0[q] + wa[q] * dn1[q] + wb[q] * dn2[q];
    out[q] = (p - m) / (p + m + eps);
  }
}

}  // namespace cuetrack::fitk::scalar
