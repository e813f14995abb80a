// The mode guard (beyond the paper; `modeGuard`): when the particle cloud has split over
// two places (the target and a look-alike beside it), its weighted mean lies between
// them, on neither. The sign is a mean that scores far below a confident best particle;
// the estimate is then the weighted mean of the best particle's mode alone. Not when no
// particle is confident: with the target hidden, the mean's low score is what tells lost
// detection it is gone.
#pragma once

#include <cstdint>

#include "cuetrack/core/Config.hpp"
#include "cuetrack/core/Geometry.hpp"
#include "cuetrack/core/ParticleFilter.hpp"
#include "cuetrack/core/Tuning.hpp"

namespace cuetrack {

class ModeGuard {
 public:
  // Scores c in [-1, 1]: the weighted mean's and the best particle's.
  static bool split(float meanScore, float bestScore) {
    return meanScore < bestScore - tuning::modeGuard::kMargin &&
           0.5f * (bestScore + 1.f) >= tuning::modeGuard::kMinConfidence;
  }
  // The weighted mean of the particles whose windows (boxes[i]) overlap the best
  // weighted particle's by at least kModeOverlap.
  Particle modeMean(const ParticleFilter& filter, const Box* boxes);

 private:
  uint8_t _inMode[kMaxParticles] = {};
};

}  // namespace cuetrack
