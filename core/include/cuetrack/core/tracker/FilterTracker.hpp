// The `dcf` configuration: the background-aware correlation filter alone as a tracker
// (issue 53): no particles, no classifier, no randomness. Each frame it searches the
// window around the last box at kScales scales, moves to the best peak, and learns
// there. It is the honest measure of the appearance model: what the filter does with
// nothing to help it.
#pragma once

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack/core/config/InitError.hpp"
#include "cuetrack/core/cues/BackgroundAwareFilter.hpp"

namespace cuetrack {

class FilterTracker {
 public:
  // Scales searched: kScaleStep to the powers -2..2 of the last box (BACF's 5 and 1.01).
  static constexpr int kScales = 5;
  static constexpr float kScaleStep = 1.01f;
  // The model's learning rate (BACF's 0.013: a target seen for ~75 frames).
  static constexpr float kLearnRate = 0.013f;

  InitError init(const Frame& frame, const Box& box);
  TrackResult update(const Frame& frame);
  bool tracking() const { return _tracking; }
  // The last update's peak to sidelobe ratio: how far the target stands out of the map.
  float sharpness() const { return _sharpness; }

 private:
  BackgroundAwareFilter _filter;
  Box _box{};
  int _imageW = 0, _imageH = 0;
  bool _tracking = false;
  float _sharpness = 0.f;
};

}  // namespace cuetrack
