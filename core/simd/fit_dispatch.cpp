// Chooses the fit kernels statically: SSE2 is baseline on x86-64, NEON on aarch64.
#include "cuetrack/core/kernels/FitKernels.hpp"

namespace cuetrack::fitk {

#if defined(CUETRACK_FITK_SSE2)
namespace isa = sse2;
const char* activeIsa() {
  return "sse2";
}
#elif defined(CUETRACK_FITK_NEON)
namespace isa = neon;
const char* activeIsa() {
  return "neon";
}
#else
namespace isa = scalar;
const char* activeIsa() {
  return "scalar";
}
#endif

void densRow(const float* lnm, float mu, float k, float norm, float* out, int n) {
  isa::densRow(lnm, mu, k, norm, out, n);
}
void bakeRow(const float* wc, const float* wa, const float* wb, const float* dp0, const float* dp1,
             const float* dp2, const float* dn0, const float* dn1, const float* dn2, float eps,
             float* out, int n) {
  isa::bakeRow(wc, wa, wb, dp0, dp1, dp2, dn0, dn1, dn2, eps, out, n);
}

}  // namespace cuetrack::fitk
