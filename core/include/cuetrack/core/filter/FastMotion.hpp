// Fast targets and slow or dropped frames (beyond the paper; `fastMotion`). After a
// learnt frame, one particle in tuning::fastMotion::kJumpEvery jumps by a few times the
// position noise (the motion models' jump()), so a target that moved further than the
// noise reaches is still found; in 2D always, in 3D only when frames come far apart (at
// 30 fps the AR(1) model keeps up, and jumps cost accuracy), and a 3D jump that the
// depth correction put on another surface is undone. In 2D a particle also coasts on its
// velocity over the frames dropped since the last one (FramePeriod).
#pragma once

#include <cstdint>

#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"

namespace cuetrack {

class FastMotion {
 public:
  static constexpr int kEvery = tuning::fastMotion::kJumpEvery;
  static_assert(kEvery >= 2, "particle 0 never jumps");

  void configure(bool enabled) { _enabled = enabled; }
  // A new track: armed (its first frame was learnt), no frame period yet.
  void start() {
    _armed = _enabled;
    _jumping = false;
    _period.clear();
  }
  // 2D: the frames elapsed since the last one, from the timestamps (1 when off or 3D).
  int framesElapsed(bool is3d, uint64_t lastUs, uint64_t nowUs) {
    return _enabled && !is3d && nowUs > lastUs ? _period.framesElapsed(nowUs - lastUs) : 1;
  }
  // Before the motion step: whether particles jump this frame.
  void beginFrame(bool is3d, float dtS) {
    _jumping = _armed && (!is3d || dtS > tuning::fastMotion::kJumpMinDtS);
  }
  bool jumping() const { return _jumping; }
  // Particle i, after its motion step, jumps if it is one of the jumpers this frame. In
  // 2D only while the tracker is sure of the target: jumps during an occlusion would
  // carry the cloud off to whatever looks most like it.
  void jump2d(int i, Particle& q, const MotionModel2d& m, Rng& rng) const {
    if (_jumping && i % kEvery == 1) m.jump(q, rng, tuning::fastMotion::kJumpScale);
  }
  void jump3d(int i, Particle& q, const MotionModel3d& m, Rng& rng, float dtS) {
    if (!_jumping || i % kEvery != 1) return;
    _preJump[i / kEvery] = q;
    m.jump(q, rng, dtS, tuning::fastMotion::kJumpScale);
  }
  // 3D, after the depth correction: if particle i jumped onto another surface (its depth
  // moved by more than kJumpMaxDepthChange of z), q is put back where it was before the
  // jump and true returned; the caller then corrects its depth again.
  bool undoOffSurface(int i, Particle& q) const;
  // After the decision: only a learnt frame arms the next frame's jumps.
  void endFrame(bool learned) { _armed = _enabled && learned; }

 private:
  bool _enabled = false;
  bool _armed = false;    // the last frame was learnt
  bool _jumping = false;  // particles jump this frame
  FramePeriod _period{};
  Particle _preJump[kMaxParticles / kEvery + 1];  // 3D: each jumper before its jump
};

}  // namespace cuetrack
