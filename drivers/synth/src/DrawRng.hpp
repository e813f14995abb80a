// The random draws of a generated scene (drawScene): splitmix64 and 2^x, log2(x) without
// libm, so a draw is the same on every architecture (the library is built with
// -ffp-contract=off).
#pragma once

#include <cstdint>

#include "SynthCommon.hpp"

namespace cuetrack::synth {

inline float exp2Det(float x) {
  const int n = floorToInt(x);
  const float y = (x - static_cast<float>(n)) * 0.69314718f;
  float term = 1.f, sum = 1.f;
  for (int k = 1; k <= 9; ++k) {
    term *= y / static_cast<float>(k);
    sum += term;
  }
  for (int i = 0; i < n; ++i) sum *= 2.f;
  for (int i = 0; i > n; --i) sum *= 0.5f;
  return sum;
}

inline float log2Det(float x) {
  int n = 0;
  while (x >= 2.f) {
    x *= 0.5f;
    ++n;
  }
  while (x < 1.f) {
    x *= 2.f;
    --n;
  }
  // ln x = 2 atanh((x - 1) / (x + 1)), z <= 1/3 here.
  const float z = (x - 1.f) / (x + 1.f), z2 = z * z;
  float t = z, s = 0.f;
  for (int k = 0; k < 10; ++k) {
    s += t / static_cast<float>(2 * k + 1);
    t *= z2;
  }
  return static_cast<float>(n) + 2.f * s / 0.69314718f;
}

struct DrawRng {
  uint64_t s;
  float unit() { return static_cast<float>(splitmix64(s) >> 40) * (1.f / 16777216.f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
  float logUniform(float lo, float hi) { return lo * exp2Det(unit() * log2Det(hi / lo)); }
  bool chance(float p) { return unit() < p; }
  float sign() { return chance(0.5f) ? 1.f : -1.f; }
  uint32_t bits() { return static_cast<uint32_t>(splitmix64(s) >> 32); }
  uint8_t byte() { return static_cast<uint8_t>(splitmix64(s) >> 56); }
};

}  // namespace cuetrack::synth
