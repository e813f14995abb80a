#include "cuetrack/core/filter/FastMotion.hpp"

namespace cuetrack {

bool FastMotion::undoOffSurface(int i, Particle& q) const {
  if (!_jumping || i % kEvery != 1) return false;
  const Particle& pre = _preJump[i / kEvery];
  const float dz = q.p[2] - pre.p[2];
  const float limit = tuning::fastMotion::kJumpMaxDepthChange * pre.p[2];
  if (dz <= limit && -dz <= limit) return false;
  q = pre;
  return true;
}

}  // namespace cuetrack
