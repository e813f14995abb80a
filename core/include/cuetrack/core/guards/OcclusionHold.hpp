// The hold behind an occluder (beyond the paper; with `occlusionGate`, 3D): lost, or
// missed, with the last learnt estimate covered by a nearer surface, the target is behind
// it. It is reported there, moved on across the view at the velocity of its learnt
// positions, while the search goes on, until found again, uncovered, or held kMaxHoldS.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/guards/Occlusion.hpp"

namespace cuetrack {

class OcclusionHold {
 public:
  static constexpr float kMaxHoldS = tuning::occlusion::kMaxHoldS;

  // A new track at q, at time tUs.
  void start(uint64_t tUs, const Particle& q) {
    _holding = false;
    _motion.clear();
    _learnt = q;
    _learntUs = tUs;
  }
  void stop() { _holding = false; }
  // The estimate q was learnt at tUs; withMotion: its position feeds the hold's velocity.
  void learnt(uint64_t tUs, const Particle& q, bool withMotion);
  // One frame at nowUs: `behind` says the target is lost or missed with its last estimate
  // covered. While holding, *lastEstimate is moved to where the target is held (x, y from
  // where it was learnt, at the learnt velocity; its depth kept). Returns holding().
  bool step(uint64_t nowUs, bool behind, Particle* lastEstimate);
  bool holding() const { return _holding; }
  const float* velocityMmPerS() const { return _heldVelocity; }

  // Whether the target's own box `targetBox` of q is mostly covered by a surface in front
  // of q's front (tuning::occlusion::kCoveredAbove).
  static bool covered(const DepthView& depthMm, const Box& targetBox, const Particle& q);

 private:
  bool _holding = false;
  uint64_t _heldSinceUs = 0, _learntUs = 0;
  Particle _learnt{};
  float _heldVelocity[3] = {0.f, 0.f, 0.f};  // [mm/s]
  LearntMotion _motion;
};

}  // namespace cuetrack
