// PLACEHOLDER until the neon kernels land: forwards to the scalar reference.
#include "cuetrack/core/Integral.hpp"

#if defined(__x86_64__) || defined(__i386__) || defined(__ARM_NEON) || defined(__ARM_NEON__)
namespace cuetrack::integral::neon {
void rgb(const Rgb8* s, int ss, int w, int h, uint32_t* g, int32_t* a, int32_t* b, int st) {
  scalar::rgb(s, ss, w, h, g, a, b, st);
}
void depth(const uint16_t* s, int ss, int w, int h, uint32_t* d, uint32_t* c, int st) {
  scalar::depth(s, ss, w, h, d, c, st);
}
void gray(const uint8_t* s, int ss, int w, int h, uint32_t* g, int st) {
  scalar::gray(s, ss, w, h, g, st);
}
}  // namespace cuetrack::integral::neon
#endif
