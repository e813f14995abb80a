// PCG32 (O'Neill 2014, XSH-RR): small, fast, and the same sequence on every platform.
// Floats are built from integer bits and the portable math in FastMath.hpp, never
// from <random>'s implementation-defined distributions.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack {

class Rng {
 public:
  explicit Rng(uint64_t seed = 0x853c49e6748fea9bULL) { reseed(seed); }

  void reseed(uint64_t seed, uint64_t stream = 0xda3e39cb94b95bdbULL) {
    _state = 0;
    _inc = (stream << 1u) | 1u;
    next();
    _state += seed;
    next();
    _hasSpare = false;
  }

  uint32_t next() {
    const uint64_t old = _state;
    _state = old * 6364136223846793005ULL + _inc;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1).
  float uniform() { return static_cast<float>(next() >> 8) * (1.f / 16777216.f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n), n > 0 (Lemire's multiply-shift; bias < 2^-32 * n).
  uint32_t below(uint32_t n) {
    return static_cast<uint32_t>((static_cast<uint64_t>(next()) * n) >> 32);
  }

  // Approximately normal, for process noise: the sum of four uniform bytes of one draw
  // (Irwin-Hall), scaled to mean 0 and variance exactly 1; tails end at +-3.45.
  float gaussianFast() {
    const uint32_t r = next();
    const int s = static_cast<int>((r & 255u) + ((r >> 8) & 255u) + ((r >> 16) & 255u) + (r >> 24));
    return (static_cast<float>(s) - 510.f) * (1.f / 147.799639f);  // sqrt(4 (256^2 - 1) / 12)
  }

  // Standard normal (Marsaglia's polar method).
  float gaussian() {
    if (_hasSpare) {
      _hasSpare = false;
      return _spare;
    }
    float u, v, s;
    do {
      u = 2.f * uniform() - 1.f;
      v = 2.f * uniform() - 1.f;
      s = u * u + v * v;
    } while (s >= 1.f || s == 0.f);
    const float f = fmath::sqrtf(-2.f * fmath::fastLog(s) / s);
    _spare = v * f;
    _hasSpare = true;
    return u * f;
  }

 private:
  uint64_t _state = 0;
  uint64_t _inc = 1;
  float _spare = 0.f;
  bool _hasSpare = false;
};

}  // namespace cuetrack
