// Where the negatives of a learning step lie (docs/algorithm.md, "Training set"): every
// other one a near miss of the estimate (shifted, or shrunk / grown), the rest background
// windows around it. The paper takes random background windows only; without the near
// misses a window inside the target scores as well as the right one, and the estimate
// shrinks.
#pragma once

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/config/TrackerConfig.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

class NegativeSampler {
 public:
  static constexpr float kRange = 1.5f;       // background within +-1.5 window sizes
  static constexpr float kMaxOverlap = 0.3f;  // ... overlapping the estimate less than this

  struct Params {
    float nearOverlap = tuning::negatives::kNearOverlap;  // near misses overlap less than this
    float shrunkScale =
        tuning::negatives::kShrunkScale;  // > 0: near misses scaled by this or 1/this
    bool anchored2d = true;               // 2D: ... anchored at the start, centre or end per axis
    float shiftedFraction =
        tuning::negatives::kShiftedFraction;  // > 0: shifted by this of the side
  };
  static Params paramsOf(const TrackerConfig& c);

  // 3D (paper 2.1): background windows sized as the cylinder (D, H in mm) would project
  // at the depth measured where they lie.
  struct Cylinder {
    const IntegralChannels* channels = nullptr;
    CameraIntrinsics k{};
    float diameterMm = 0.f, heightMm = 0.f;
    int imageW = 0, imageH = 0;
  };

  void configure(const Params& p) { _p = p; }
  // The k-th negative of a learning step around `around` (k's parity and bit 1 choose its
  // type), inside `roi`; `cylinder` is null in 2D.
  Box next(int k, const Box& around, const PixelRect& roi, const Cylinder* cylinder,
           Rng& rng) const;

 private:
  Params _p{};
};

}  // namespace cuetrack
