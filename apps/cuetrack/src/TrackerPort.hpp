// The app's view of the tracker: the real cuetrack::Tracker in the shipped binary
// (CoreTracker), a tiny deterministic stand-in in pipeline tests. Keeps the app's
// wiring testable without the multi-MiB core.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/TrackResult.hpp"

namespace cuetrack::app {

class TrackerPort {
 public:
  virtual ~TrackerPort() = default;
  // Preset name ("best", "1.1"...). False for an unknown name (the tracker refuses no
  // preset's configuration: test_core_tracker checks every one).
  virtual bool configure(const char* preset, uint64_t seed, const Clock* clock) = 0;
  // 0 on success, else a nonzero reason with a one-line text in *why.
  virtual int init(const Frame& frame, const Box& box, const char** why) = 0;
  virtual TrackResult update(const Frame& frame) = 0;
  virtual void reset() = 0;
};

}  // namespace cuetrack::app
