#include "cuetrack/core/config/ConfigError.hpp"

namespace cuetrack {

const char* toString(ConfigError e) {
  switch (e) {
    case ConfigError::None:
      return "ok";
    case ConfigError::ParticlesOutOfRange:
      return "numParticles outside 1..2000";
    case ConfigError::WeakClassifiersOutOfRange:
      return "numWeakClassifiers outside 1..32";
    case ConfigError::WeakClassifiers2dOutOfRange:
      return "numWeakClassifiers2d outside 0..32 (0: the 3D value)";
    case ConfigError::LostAfter2dNegative:
      return "lostAfter2d below 0 (0: the 3D value)";
    case ConfigError::NoFeatures:
      return "no feature kind (useGray, useColour, useDepth all off)";
    case ConfigError::UnknownStateSpace:
      return "stateSpace is not a StateSpace";
    case ConfigError::UnknownSampling:
      return "sampling is not a FeatureSampling";
  }
  return "unknown error";
}

ConfigError validate(const TrackerConfig& c) {
  static_assert(kMaxParticles == 2000 && kMaxWeakClassifiers == 32,
                "toString(ConfigError) names these capacities");
  if (c.numParticles < 1 || c.numParticles > kMaxParticles) return ConfigError::ParticlesOutOfRange;
  if (c.numWeakClassifiers < 1 || c.numWeakClassifiers > kMaxWeakClassifiers)
    return ConfigError::WeakClassifiersOutOfRange;
  if (c.numWeakClassifiers2d < 0 || c.numWeakClassifiers2d > kMaxWeakClassifiers)
    return ConfigError::WeakClassifiers2dOutOfRange;
  if (c.lostAfter2d < 0) return ConfigError::LostAfter2dNegative;
  if (!c.useGray && !c.useColour && !c.useDepth) return ConfigError::NoFeatures;
  if (c.stateSpace != StateSpace::Image2d && c.stateSpace != StateSpace::Cylinder3d)
    return ConfigError::UnknownStateSpace;
  if (c.sampling != FeatureSampling::Dense && c.sampling != FeatureSampling::Sparse)
    return ConfigError::UnknownSampling;
  return ConfigError::None;
}

}  // namespace cuetrack
