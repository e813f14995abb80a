// One update's scratch for a set of windows (every particle's, or those the Reseeder
// moved): each one's window, whether it is scored, the classifier's score and the
// appearance cue's response there, sized together (FixedVector: the count is the
// vectors' size, not a separate int).
#pragma once

#include <cstdint>

#include "cuetrack/core/base/FixedVector.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

template <int N>
struct WindowScratch {
  FixedVector<Box, N> boxes;      // each one's window [px]
  FixedVector<uint8_t, N> valid;  // scored (else its score is -1)
  FixedVector<float, N> scores;   // the classifier's score c in [-1, 1]
  FixedVector<float, N> cue;      // the appearance cue's response at its centre

  // n windows (false, and the sizes kept, past the capacity N).
  bool resize(int n) {
    if (n < 0 || n > N) return false;
    boxes.resize(n);
    valid.resize(n);
    scores.resize(n);
    cue.resize(n);
    return true;
  }
  int size() const { return boxes.size(); }
};

using ParticleScratch = WindowScratch<kMaxParticles>;

}  // namespace cuetrack
