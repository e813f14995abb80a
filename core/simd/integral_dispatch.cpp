// Chooses the integral-image implementation: static on ARM (NEON is part of the
// target), a one-time CPUID check for AVX2 on x86 (SSE2 is baseline on x86-64).
#include "cuetrack/core/Integral.hpp"

namespace cuetrack::integral {

#if defined(__x86_64__) || defined(__i386__)
bool avx2Available() {
  static const bool kHas = __builtin_cpu_supports("avx2");
  return kHas;
}
#define CUETRACK_PICK(fn, ...) (avx2Available() ? avx2::fn(__VA_ARGS__) : sse2::fn(__VA_ARGS__))
const char* activeIsa() {
  return avx2Available() ? "avx2" : "sse2";
}
#elif defined(__ARM_NEON) || defined(__ARM_NEON__)
bool avx2Available() {
  return false;
}
#define CUETRACK_PICK(fn, ...) neon::fn(__VA_ARGS__)
const char* activeIsa() {
  return "neon";
}
#else
bool avx2Available() {
  return false;
}
#define CUETRACK_PICK(fn, ...) scalar::fn(__VA_ARGS__)
const char* activeIsa() {
  return "scalar";
}
#endif

void rgb(const Rgb8* src, int srcStride, int width, int height, uint32_t* g, int32_t* a, int32_t* b,
         int sumStride) {
  CUETRACK_PICK(rgb, src, srcStride, width, height, g, a, b, sumStride);
}
void depth(const uint16_t* srcMm, int srcStride, int width, int height, uint32_t* sumMm,
           uint32_t* count, int sumStride) {
  CUETRACK_PICK(depth, srcMm, srcStride, width, height, sumMm, count, sumStride);
}
void gray(const uint8_t* src, int srcStride, int width, int height, uint32_t* sum, int sumStride) {
  CUETRACK_PICK(gray, src, srcStride, width, height, sum, sumStride);
}

}  // namespace cuetrack::integral
