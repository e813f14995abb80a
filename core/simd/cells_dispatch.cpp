// Chooses the cell coder statically: SSE2 is baseline on x86-64, NEON on aarch64.
#include "cuetrack/core/CellKernels.hpp"

namespace cuetrack::cellk {

#if defined(CUETRACK_CELLK_SSE2)
namespace isa = sse2;
const char* activeIsa() {
  return "sse2";
}
#elif defined(CUETRACK_CELLK_NEON)
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

}  // namespace cuetrack::cellk
