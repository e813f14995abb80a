// Chooses the cell coder: on x86-64 AVX2 after a CPUID check, else SSE2 (baseline);
// NEON on aarch64, else scalar.
#include "cuetrack/core/kernels/Integral.hpp"
#include "cuetrack/core/model/CellKernels.hpp"

namespace cuetrack::cellk {

#if defined(CUETRACK_CELLK_SSE2)
// libgcc reads the CPU model once before main (as integral_dispatch.cpp).
const char* activeIsa() {
  return integral::avx2Available() ? "avx2" : "sse2";
}
int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  if (integral::avx2Available()) return avx2::codeFrame(kind, f, t, wins, valid, n, cells, order);
  return sse2::codeFrame(kind, f, t, wins, valid, n, cells, order);
}
#else
#if defined(CUETRACK_CELLK_NEON)
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
int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  return isa::codeFrame(kind, f, t, wins, valid, n, cells, order);
}
#endif

}  // namespace cuetrack::cellk
