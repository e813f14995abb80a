// Chooses the integral-image implementation: static on ARM (NEON is part of the
// target), on x86 SSE2 (baseline on x86-64) plus a one-time CPUID check for AVX2.
// AVX2 is used where it measured faster (docs/benchmarks.md, "Integral images"):
// the fused RGB pass (~1.3x over SSE2); for depth and gray8 SSE2 is as fast or
// faster (the passes are bound by loads/stores, and the 8-lane prefix costs a
// cross-lane shuffle), so those stay on SSE2.
#include "cuetrack/core/kernels/Integral.hpp"

namespace cuetrack::integral {

#if defined(__x86_64__) || defined(__i386__)
// libgcc fills the CPU model (including the OS's YMM support) before main; reading
// it is one load, and no function-local static (core has no thread-safe statics).
bool avx2Available() {
  return __builtin_cpu_supports("avx2");
}
const char* activeIsa() {
  return avx2Available() ? "avx2+sse2" : "sse2";
}
void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* g, int32_t* a, int32_t* b,
         int sumStride) {
  if (avx2Available()) {
    avx2::rgb(src, srcStride, width, height, g, a, b, sumStride);
  } else {
    sse2::rgb(src, srcStride, width, height, g, a, b, sumStride);
  }
}
#define CUETRACK_PICK(fn, ...) sse2::fn(__VA_ARGS__)
#else
bool avx2Available() {
  return false;
}
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
#define CUETRACK_PICK(fn, ...) neon::fn(__VA_ARGS__)
const char* activeIsa() {
  return "neon";
}
#else
#define CUETRACK_PICK(fn, ...) scalar::fn(__VA_ARGS__)
const char* activeIsa() {
  return "scalar";
}
#endif
void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* g, int32_t* a, int32_t* b,
         int sumStride) {
  CUETRACK_PICK(rgb, src, srcStride, width, height, g, a, b, sumStride);
}
#endif

void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  CUETRACK_PICK(depth, srcMm, srcStride, width, height, sumMm, count, sumStride);
}
void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  CUETRACK_PICK(gray, src, srcStride, width, height, sum, sumStride);
}

}  // namespace cuetrack::integral
