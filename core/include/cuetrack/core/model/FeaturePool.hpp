// The candidate features GentleBoost chooses from (paper 2.3): per enabled kind a
// fixed grid of static features plus kDynamicFeaturesPerKind dynamic ones; the
// dynamic part is renewed one feature per update, the static part never changes.
//   Sparse (the paper): static grid tiles the window at sizes 1/2, 1/3, 1/4
//     (4 + 9 + 16 = 29 per kind, plus the whole window) + 50 dynamic per kind;
//     colour positions ~ N((0.5,0.5), 0.15^2 I) truncated to [0,1]^2, others uniform.
//   Dense (Klein's old pool, tests x.3/x.4): the same sizes at half-size steps
//     (9 + 25 + 49 + 1 = 84 per kind, ~3x denser), no dynamic features.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/config/TrackerConfig.hpp"
#include "cuetrack/core/model/Features.hpp"

namespace cuetrack {

class FeaturePool {
 public:
  // Fills the pool for the enabled kinds; false if it would not fit (never with the presets).
  bool build(bool useGray, bool useDepth, bool useColour, FeatureSampling sampling, Rng& rng);
  int size() const { return _n; }
  const Feature& operator[](int i) const { return _f[i]; }
  int count(FeatureKind k, bool dynamicOnly) const;

  // One pool update (paper 2.3): a kind is chosen for removal with probability
  // proportional to its mean training error and one for addition proportional to
  // (1 - mean error); the dynamic feature of the removal kind with the highest error
  // is replaced, in place, by a new sample of the addition kind. Returns the index
  // replaced (its cached responses are stale) or -1 when nothing could be replaced.
  int update(const float* errors, Rng& rng);

  static Feature sample(FeatureKind kind, Rng& rng);

 private:
  void addGrid(FeatureKind kind, bool dense);
  bool push(const Feature& f);

  Feature _f[kMaxPoolFeatures];
  int _n = 0;
  bool _enabled[kNumFeatureKinds] = {};
};

}  // namespace cuetrack
