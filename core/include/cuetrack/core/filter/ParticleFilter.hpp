// Condensation (Isard & Blake 1998) in fixed memory: particles, their motion
// models, the 3D depth correction, weights and low-variance resampling.
//
// One particle layout serves both state spaces:
//   2D (Klein):  p = (u, v, -) window centre [px], v = (du, dv, -) [px/frame],
//                size = (w, h) [px]
//   3D (paper):  p = (x, y, z) cylinder centre, camera coordinates [mm],
//                v = velocity [mm/s], size = (D, H) diameter and height [mm]
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Camera.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

struct Particle {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  Eigen::Vector3f v = Eigen::Vector3f::Zero();
  Eigen::Vector2f size = Eigen::Vector2f::Zero();
};

// 2D: first-order AR on the window centre plus scale and aspect random walks.
// Noise std per frame, as fractions of the window's mean side sqrt(w h).
struct MotionModel2d {
  float positionNoise = tuning::motion2d::kPositionNoise;
  float velocityNoise = tuning::motion2d::kVelocityNoise;
  float velocityDecay = tuning::motion2d::kVelocityDecay;
  float scaleNoise = tuning::motion2d::kScaleNoise;
  float aspectNoise = tuning::motion2d::kAspectNoise;
  // framesElapsed > 1 when frames were dropped: the velocity is per frame, so the
  // particle coasts that many frames (the noise stays one frame's: see FramePeriod).
  void predict(Particle& q, Rng& rng, float spread, int framesElapsed = 1) const;
  // A jump of scale x the position noise, taken into the velocity as well, so that a
  // particle that lands on a fast target keeps moving with it (TrackerConfig::fastMotion).
  void jump(Particle& q, Rng& rng, float scale) const;
};

// The frames elapsed since the last one given to the tracker, from the timestamps: the
// gap over the median of the last few gaps (the frame period), rounded, in 1..kMaxGap.
// A steady stream, at any rate, gives 1 every frame; a dropped frame gives 2.
class FramePeriod {
 public:
  static constexpr int kHistory = 9;
  static constexpr int kMaxGap = 4;
  void clear() { _count = 0; }
  int framesElapsed(uint64_t dtUs);

 private:
  uint64_t _dtUs[kHistory] = {};
  int _count = 0, _next = 0;
};

// 3D: the paper's AR(1), r' = r + v dt, v' = v + N(0, sigma^2 dt I), with sigma^2 the
// velocity noise variance accrued per second [mm^2/s^2 per s]; plus a position
// diffusion of positionNoise x D per sqrt(frame of 1/30 s) (see docs/algorithm.md:
// the paper's 550 mm^2/s^2 alone moves particles by under a millimetre per frame),
// and, when size adaptation is on, random walks of ln D and ln H.
struct MotionModel3d {
  float velocityNoiseMm2PerS2 = tuning::motion3d::kVelocityNoiseMm2PerS2;
  float positionNoise = tuning::motion3d::kPositionNoise;
  float sizeNoise = 0.f;  // std of ln(D), ln(H) per frame; 0 = fixed cylinder (paper)
  void predict(Particle& q, Rng& rng, float dtS, float spread) const;
  // A sideways jump (x, y) of scale x the position noise over dtS, taken into the
  // velocity as well (TrackerConfig::fastMotion); the depth correction then sets z.
  void jump(Particle& q, Rng& rng, float dtS, float scale) const;
};

// The cylinder's projection: an upright cylinder seen by a pinhole camera is a
// rectangle fx D / z wide and fy H / z high around the projected centre.
Box projectCylinder(const Particle& q, const CameraIntrinsics& k);

// A new track's cylinder from its box and the depth of the surface seen in it: the
// silhouette is fx D / z_centre wide with z_centre = surface + D/2.
Particle cylinderFromBox(const Box& b, float surfaceMm, const CameraIntrinsics& k);

// A window kept sane: no larger than the image, at least kMinWindowPx a side, and at
// least half inside the image.
inline Box saneWindow(const Box& b, int imageW, int imageH) {
  Box r = b;
  const float iw = static_cast<float>(imageW), ih = static_cast<float>(imageH);
  if (r.w > iw) r.w = iw;
  if (r.h > ih) r.h = ih;
  if (r.w < kMinWindowPx) r.w = kMinWindowPx;
  if (r.h < kMinWindowPx) r.h = kMinWindowPx;
  r.x = fmath::clampf(r.x, -0.5f * r.w, iw - 0.5f * r.w);
  r.y = fmath::clampf(r.y, -0.5f * r.h, ih - 0.5f * r.h);
  return r;
}

// A particle's window in the image: its cylinder's projection in 3D, its box in 2D.
inline Box particleWindow(const Particle& q, bool is3d, const CameraIntrinsics& k) {
  if (is3d) return projectCylinder(q, k);
  return Box{q.p[0] - 0.5f * q.size[0], q.p[1] - 0.5f * q.size[1], q.size[0], q.size[1]};
}

// A guard (every 3D preset): keep the cylinder's projected centre inside the image and
// its centre depth in [kMinCylinderDepthMm, kMaxDepthMm], zeroing the velocity
// component that pushed it out. A particle whose centre leaves the image has nothing to
// be weighed on (no depth correction, no colour) and would otherwise coast away on its
// velocity; while the target is in view the guard never acts. Returns true when it did.
inline constexpr float kMinCylinderDepthMm = 300.f;
bool keepInView(Particle& q, const CameraIntrinsics& k, int imageW, int imageH);

// Depth correction phi (paper eq. 2): average the valid depth inside the inner 10%
// of the projection, move the particle along its viewing ray so its front surface
// (centre depth - D/2) lies at that depth, and add the move / dt to its velocity.
// Returns false (particle untouched) when the inner rectangle has no valid depth.
// Below kMinVelocityDtS (a repeated frame; cameras run at <= 200 Hz) the velocity is kept.
inline constexpr float kMinVelocityDtS = 0.005f;
bool correctDepth(Particle& q, const IntegralChannels& ch, const CameraIntrinsics& k, float dtS,
                  int imageW, int imageH);

class ParticleFilter {
 public:
  int size() const { return _n; }
  void setSize(int n) { _n = n < 1 ? 1 : (n > kMaxParticles ? kMaxParticles : n); }
  Particle& operator[](int i) { return _p[i]; }
  const Particle& operator[](int i) const { return _p[i]; }
  float* weights() { return _w; }
  const float* weights() const { return _w; }
  // Every particle a copy of q.
  void fill(const Particle& q);
  // The weights from the classifier's scores: w = exp(lambda (c - c_max)), plus, when
  // the appearance cue answered (cueScores, else null), its gain x (r - r_max).
  // (scores, cueScores: one per particle; cueScores empty when the cue did not answer.)
  void weigh(Span<const float> scores, Span<const float> cueScores);
  // The weighted mean overlap of the particles' windows `boxes` with `estimate`.
  float concentration(Span<const Box> boxes, const Box& estimate) const;
  // Every particle's velocity zeroed (searching: the cloud spreads around where it is).
  void forgetVelocities() {
    for (int i = 0; i < _n; ++i) _p[i].v.setZero();
  }
  // Low-variance (systematic) resampling by the current weights; one uniform draw.
  void resample(Rng& rng);
  int argmaxWeight() const;
  // Weighted mean of all particles, or of those with include[i] != 0 (weights need not
  // be normalised); particle 0 when the included weights sum to zero.
  Particle weightedMean(const uint8_t* include = nullptr) const;

 private:
  Particle _p[kMaxParticles];
  Particle _scratch[kMaxParticles];
  float _w[kMaxParticles] = {};
  int _n = 1;
};
// 2 x 2000 particles x 32 B + 2000 x 4 B = 136,000 B.
static_assert(sizeof(Particle) == 32, "Particle is 8 floats");

}  // namespace cuetrack
