// The state space a track runs in, chosen once at init (SpaceChoice): 2D windows or 3D
// cylinders, with the camera, the image size, the motion models and the 2D size filter.
// Everything that differs between the two lives here: a particle's window, its motion
// step, the initial particle, keeping it sane, the depth correction (3D) and the
// cylinder the negatives are drawn around (3D). Tracker asks; it does not branch.
#pragma once

#include "cuetrack/core/base/Camera.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack/core/cues/SizeFilter.hpp"
#include "cuetrack/core/filter/FastMotion.hpp"
#include "cuetrack/core/filter/LostSearch.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"
#include "cuetrack/core/model/NegativeSampler.hpp"

namespace cuetrack {

class Space {
 public:
  // The configuration's part (Tracker::configure): adaptsSize: the cylinder's D and H
  // follow the target (adaptCylinderSize), so the 3D motion walks them too.
  void configure(bool adaptsSize);
  // A new track: the space SpaceChoice chose, the frame's camera and size.
  void start(bool is3d, const CameraIntrinsics& k, int imageW, int imageH);

  bool is3d() const { return _is3d; }
  // 3D with adaptCylinderSize: CylinderSizer follows the depth silhouette.
  bool sizesCylinder() const { return _is3d && _adaptsSize; }
  // The appearance cue searches scales in 2D only: in 3D the depth sets the scale.
  bool cueSearchesScales() const { return !_is3d; }
  int imageW() const { return _w; }
  int imageH() const { return _h; }
  const CameraIntrinsics& camera() const { return _k; }
  SearchView view() const { return SearchView{_is3d, _k, _w, _h}; }

  // Particle q's window: its cylinder's projection in 3D, its box in 2D.
  Box window(const Particle& q) const { return particleWindow(q, _is3d, _k); }
  // A window no larger than the image, at least kMinWindowPx a side, half inside.
  Box sane(const Box& b) const { return saneWindow(b, _w, _h); }
  bool insideEnough(const Box& b) const { return cuetrack::insideEnough(b, _w, _h); }
  // Whether window b can be scored: at least 4 px a side and touching the image; while
  // searching (lost), mostly inside it (a window half outside scores on whatever its
  // features read there).
  bool scorable(const Box& b, bool searching) const;
  // The particle a track starts from, on window b (3D: standing at surfaceMm).
  Particle initial(const Box& b, float surfaceMm) const;
  // The training set's first positives: how many, and their jitter (fraction of a side).
  int initialPositives() const;
  float initialJitter() const;

  // Particle i's motion step (spread: the noise's factor while lost; framesElapsed: 2D
  // coasting over dropped frames), its fast-motion jump, and keepSane.
  void predict(int i, Particle& q, FastMotion& fast, Rng& rng, float dtS, float spread,
               int framesElapsed) const;
  // 3D: the projected centre in the image and the depth in range (keepInView); 2D: the
  // window sane and near the image.
  void keepSane(Particle& q) const;
  // 3D with depth (paper eq. 2): every particle of `filter` onto the measured surface,
  // boxes[i] its new window; a fast-motion jump that landed on another surface undone.
  // 2D, or no depth: nothing.
  void correctDepths(bool hasDepth, float dtS, const IntegralChannels& channels,
                     const FastMotion& fast, ParticleFilter& filter, Span<Box> boxes) const;
  // 3D: the cylinder the negatives are drawn around (the last learnt estimate's size),
  // written to *out and returned; 2D: null.
  const NegativeSampler::Cylinder* negativesCylinder(const IntegralChannels& channels,
                                                     const Particle& last,
                                                     NegativeSampler::Cylinder* out) const;
  // 3D: the result's position is particle `at`'s, its depth predicted (not measured) when
  // the inner half of its target box `targetBox` has too little valid depth in
  // `channels` (tuning::kMinDepthSupport). 2D: no position.
  void report(TrackResult* r, const Particle& at, const Box& targetBox,
              const IntegralChannels& channels) const;
  // 2D: the estimate's size smoothed (SizeFilter2d); 3D: b as it is.
  void resetSize(const Box& b) { _sizeFilter.reset(b); }
  Box filterSize(const Box& b);

 private:
  bool _is3d = false;
  bool _adaptsSize = false;
  CameraIntrinsics _k{};
  int _w = 0, _h = 0;
  MotionModel2d _motion2d{};
  MotionModel3d _motion3d{};
  SizeFilter2d _sizeFilter{};  // 2D: the estimate's size, smoothed
};

}  // namespace cuetrack
