// 3D (beyond the paper): a surface nearer than the target inside its box says something
// covers it (a look-alike passing in front, a board, a hand). Such a frame is not learnt:
// the classifier and the template would take the occluder in as the target.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack::occlusion {

// Samples per axis of the box (a grid of at most kGrid x kGrid depth reads).
inline constexpr int kGrid = 16;

// The fraction of valid depth samples (0 = missing: not counted) on a grid over `box`
// that are nearer than nearMm; 0 when the box has no valid sample.
float nearerFraction(const DepthView& depth, const Box& box, float nearMm);

// The target's front surface (its box's middle) at frontMm, its diameter diameterMm: the
// depth in front of which a surface is taken for an occluder. The target's own relief
// (a box turned corner-on reaches up to D/2 in front of its middle) and depth noise stay
// behind it.
float occluderBelowMm(float frontMm, float diameterMm);

}  // namespace cuetrack::occlusion

namespace cuetrack {

// The target's velocity while it is hidden: the least-squares slope of the positions of
// the last kSamples learnt frames against their times. One particle's velocity is too
// noisy for it (the cloud's mean velocity on the look-alike scene: 30-120 mm/s off a
// 40 mm/s target); a slope over half a second of positions is not.
class LearntMotion {
 public:
  static constexpr int kSamples = 16;
  // Fewer samples than this, or spanning less than kMinSpanS: no velocity (zero).
  static constexpr int kMinSamples = 8;
  static constexpr float kMinSpanS = 0.2f;
  // Samples older than this before the newest are not taken (the target may have
  // turned): the slope spans at most this.
  static constexpr float kMaxSpanS = 1.f;

  void clear() { _count = _next = 0; }
  void add(uint64_t timeUs, const float p[3]);
  // The velocity [units of p per s] at the newest sample; false (and zero) when there is
  // too little to fit.
  bool velocity(float out[3]) const;

 private:
  uint64_t _timeUs[kSamples] = {};
  float _p[kSamples][3] = {};
  int _count = 0, _next = 0;
};

}  // namespace cuetrack
