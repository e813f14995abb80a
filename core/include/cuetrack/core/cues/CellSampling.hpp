// What the two correlation filters' cell features (CellFeatures, HogCnFeatures) share: a
// window's bilinear sample positions, and a gradient's orientation bin found by counting
// the bin boundaries it is past (no atan2, no branch). One copy, so both give the same
// bits for the same pixels.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack::cellSampling {

// Bilinear source position of a sample along an axis: its two pixels (clamped to
// [0, size)) and the weight of the second.
struct Tap {
  int i0, i1;
  float f;
};
inline Tap tapAt(float pos, int size) {
  const int lo = fmath::floorToInt(pos);
  Tap t{lo, lo + 1, pos - static_cast<float>(lo)};
  if (t.i0 < 0) t.i0 = 0;
  if (t.i1 < 0) t.i1 = 0;
  if (t.i0 > size - 1) t.i0 = size - 1;
  if (t.i1 > size - 1) t.i1 = size - 1;
  return t;
}

inline constexpr int kOrientations = 9;  // unsigned; 18 signed
// The unsigned bins' boundaries: bin k holds orientations within pi / 18 of k pi / 9;
// boundary b is at (2b + 1) pi / 18, as the (cos, sin) of that angle.
inline constexpr float kBoundCos[kOrientations] = {0.984807753f,  0.866025404f,  0.642787610f,
                                                   0.342020143f,  0.000000000f,  -0.342020143f,
                                                   -0.642787610f, -0.866025404f, -0.984807753f};
inline constexpr float kBoundSin[kOrientations] = {0.173648178f, 0.500000000f, 0.766044443f,
                                                   0.939692621f, 1.000000000f, 0.939692621f,
                                                   0.766044443f, 0.500000000f, 0.173648178f};

// The signed orientation bin of gradient (dx, dy): bin k of 18 centred at k pi / 9 over
// the whole circle (its unsigned bin is k % 9).
inline uint8_t signedBin(float dx, float dy) {
  const bool flip = dy < 0.f || (dy == 0.f && dx < 0.f);  // into [0, pi)
  dx = flip ? -dx : dx;
  dy = flip ? -dy : dy;
  int past = 0;
  for (int b = 0; b < kOrientations; ++b)
    past += (dy * kBoundCos[b] - dx * kBoundSin[b] > 0.f) ? 1 : 0;
  return static_cast<uint8_t>(flip ? (past + kOrientations) % (2 * kOrientations) : past);
}

}  // namespace cuetrack::cellSampling
