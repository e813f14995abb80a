// The tracker's public face. The implementation (core/src/) owns every buffer by
// value; construct once (static storage or one allocation at start-up), then
// init/update never allocate, never throw.
//
// Contract for every user (apps, tests, bench):
//   static Tracker tracker;                       // ~MiBs: not on the stack
//   tracker.configure(presetConfig(Preset::Best), seed, &clock);
//   if (tracker.init(frame, box) != InitError::None) ...
//   TrackResult r = tracker.update(nextFrame);
#pragma once

#include <cstdint>

#include "cuetrack/core/Clock.hpp"
#include "cuetrack/core/Frame.hpp"
#include "cuetrack/core/TrackResult.hpp"
#include "cuetrack/core/TrackerConfig.hpp"

namespace cuetrack {

enum class InitError : uint8_t {
  None = 0,
  EmptyBox,         // w or h <= 0
  BoxOutsideImage,  // box does not intersect the image
  BoxTooSmall,      // smaller than the smallest feature support
  NoColour,         // frame without colour image
  ImageTooLarge,    // larger than kMaxImageWidth x kMaxImageHeight
  NoDepth,          // 3D state space without depth, or no valid depth inside the box
  NoIntrinsics,     // 3D state space without camera intrinsics
};
const char* toString(InitError e);

// The members are components (particle filter, observation model, feature
// pool, training set), each a fixed-size class of its own; Tracker only wires
// them. It is large (MiBs): give it static storage or allocate it once.
class Tracker {
 public:
  Tracker();

  // Chooses the configuration, the random seed and an optional clock for stage timings.
  void configure(const TrackerConfig& config, uint64_t seed, const Clock* clock = nullptr);
  InitError init(const Frame& frame, const Box& box);
  TrackResult update(const Frame& frame);
  void reset();  // back to Idle; keeps the configuration
  const TrackerConfig& config() const;

 private:
  // (components: defined by the core implementation)
};

}  // namespace cuetrack
