// Re-acquisition while lost (beyond the paper; with `lostDetection`). Every kEvery-th
// particle is drawn anew each frame: half anywhere in the image, half around the last
// confidently learnt estimate within a radius that grows with the frames lost; the rest
// of the cloud keeps following the best candidate so that the lost detector can confirm
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

// The image and state space the search works in.
struct SearchView {
  bool is3d = false;
  CameraIntrinsics k{};
  int imageW = 0, imageH = 0;
  Box window(const Particle& q) const { return particleWindow(q, is3d, k); }
};

class LostSearch {
 public:
  static constexpr int kEvery = tuning::search::kEvery;

  static bool drawsAnew(int i) { return i % kEvery == 0; }
  // Particle i's fresh draw while lost for `framesLost` frames: the last learnt estimate
  // `last` (without velocity) moved to an image point anywhere (every other one) or
  // around where it was; in 3D at its depth on the ray through that point, so that the
  // depth correction puts it on the surface there at the size the target would have.
  static Particle draw(int i, const Particle& last, int framesLost, const SearchView& view,
                       Rng& rng);
};

}  // namespace cuetrack
