#include "cuetrack/core/ModeGuard.hpp"

namespace cuetrack {

Particle ModeGuard::modeMean(const ParticleFilter& filter, const Box* boxes) {
  const Box top = boxes[filter.argmaxWeight()];
  const int n = filter.size();
  for (int i = 0; i < n; ++i)
    _inMode[i] = overlap(boxes[i], top) >= tuning::modeGuard::kModeOverlap ? 1 : 0;
  return filter.weightedMean(_inMode);
}

}  // namespace cuetrack
