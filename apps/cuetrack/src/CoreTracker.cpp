#include "CoreTracker.hpp"

namespace cuetrack::app {

bool CoreTracker::configure(const char* preset, uint64_t seed, const Clock* clock) {
  Preset p;
  if (!parsePreset(preset, &p)) return false;
  return _tracker.configure(presetConfig(p), seed, clock) == ConfigError::None;
}

int CoreTracker::init(const Frame& frame, const Box& box, const char** why) {
  const InitError e = _tracker.init(frame, box);
  *why = toString(e);
  return static_cast<int>(e);
}

}  // namespace cuetrack::app
