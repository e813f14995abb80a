// Whether a TrackerConfig can be run, and if not why: Tracker::configure refuses an
// invalid one (and keeps the configuration it had) instead of clamping it silently.
#pragma once

#include <cstdint>

#include "cuetrack/core/config/TrackerConfig.hpp"

namespace cuetrack {

enum class ConfigError : uint8_t {
  None = 0,
  ParticlesOutOfRange,          // numParticles outside 1..kMaxParticles
  WeakClassifiersOutOfRange,    // numWeakClassifiers outside 1..kMaxWeakClassifiers
  WeakClassifiers2dOutOfRange,  // numWeakClassifiers2d outside 0..kMaxWeakClassifiers
  LostAfter2dNegative,          // lostAfter2d below 0 (0: the 3D value)
  NoFeatures,                   // none of useGray, useColour, useDepth
  UnknownStateSpace,            // stateSpace not a StateSpace value
  UnknownSampling,              // sampling not a FeatureSampling value
};
const char* toString(ConfigError e);

// The first reason `config` cannot run, or ConfigError::None. Every preset is valid.
ConfigError validate(const TrackerConfig& config);

}  // namespace cuetrack
