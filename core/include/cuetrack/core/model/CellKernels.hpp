// StrongClassifier::evaluateMany's inner loop on frame tables: the weak-classifier table
// cell (WeakClassifier::cellOf) of one feature on n windows, visited in `order` (or
// 0..n-1), kLutCells for windows with valid[i] == 0. Returns how many windows (in visiting
// order) it coded. `scalar` is the reference: all n windows, any kind. The SIMD versions
// code Gray and Colour features 4 windows per instruction with the scalar operations per
// lane, bit-exact (tests/simd/test_simd_cells): n rounded down to a multiple of 4
// windows, and none of a Depth feature.
#pragma once

#include <cstdint>

#include "cuetrack/core/model/Features.hpp"

namespace cuetrack::cellk {

#define CUETRACK_CELLK_DECLARE_ISA(ns)                                                     \
  namespace ns {                                                                           \
  int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins, \
                const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order);      \
  }

CUETRACK_CELLK_DECLARE_ISA(scalar)
#if defined(__x86_64__) || defined(__SSE2__)
#define CUETRACK_CELLK_SSE2 1
#define CUETRACK_CELLK_AVX2 1
CUETRACK_CELLK_DECLARE_ISA(sse2)
CUETRACK_CELLK_DECLARE_ISA(avx2)  // 8 windows at a time; only where the CPU has AVX2
#endif
// aarch64 only: ARMv7 NEON flushes subnormals and has no vector division.
#if defined(__aarch64__) && defined(__ARM_NEON)
#define CUETRACK_CELLK_NEON 1
CUETRACK_CELLK_DECLARE_ISA(neon)
#endif
#undef CUETRACK_CELLK_DECLARE_ISA

// The implementation this build uses (AVX2 or SSE2 on x86-64, NEON on aarch64, else scalar);
// returns how many windows (in visiting order) it coded.
int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order);
const char* activeIsa();

}  // namespace cuetrack::cellk
