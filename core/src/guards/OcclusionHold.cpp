#include "cuetrack/core/guards/OcclusionHold.hpp"

namespace cuetrack {

void OcclusionHold::learnt(uint64_t tUs, const Particle& q, bool withMotion) {
  _learnt = q;
  _learntUs = tUs;
  if (withMotion) {
    const float p[3] = {q.p[0], q.p[1], q.p[2]};
    _motion.add(tUs, p);
  }
}

bool OcclusionHold::step(uint64_t nowUs, bool behind, Particle* lastEstimate) {
  if (behind && !_holding) {
    _heldSinceUs = nowUs;
    _motion.velocity(_heldVelocity);
  }
  _holding = behind && static_cast<float>(nowUs - _heldSinceUs) * 1e-6f < kMaxHoldS;
  if (!_holding) return false;
  // From where it was learnt (an earlier hold may have moved the estimate), across the
  // view only (x, y: what brings the target out from behind the occluder), not in depth.
  const float sinceS = static_cast<float>(nowUs - _learntUs) * 1e-6f;
  for (int a = 0; a < 2; ++a) lastEstimate->p[a] = _learnt.p[a] + _heldVelocity[a] * sinceS;
  return true;
}

bool OcclusionHold::covered(const DepthView& depthMm, const Box& targetBox, const Particle& q) {
  // Against the target's front surface.
  const float frontMm = q.p[2] - 0.5f * q.size[0];
  return occlusion::nearerFraction(depthMm, targetBox,
                                   occlusion::occluderBelowMm(frontMm, q.size[0])) >
         tuning::occlusion::kCoveredAbove;
}

}  // namespace cuetrack
