// The two small decisions around learning: whether to learn from this frame
// (the paper's update gate) and, beyond the paper, whether the target is lost.
#pragma once

#include <cstdint>

#include "cuetrack/core/TrackResult.hpp"

namespace cuetrack {

// Learn only when the classifier is confident at the estimate and the particle
// cloud agrees with it (weighted mean overlap of particles with the estimate).
struct UpdateGate {
  float minConfidence = 0.55f;
  float minConcentration = 0.5f;
  bool open(float confidence, float concentration, TrackState state) const {
    return state == TrackState::Tracking && confidence >= minConfidence &&
           concentration >= minConcentration;
  }
};

// Lost after `lostAfter` consecutive frames with confidence below `lostBelow`;
// found again after `foundAfter` consecutive frames at or above `foundAbove`.
class LostDetector {
 public:
  float lostBelow = 0.42f;
  float foundAbove = 0.58f;
  int lostAfter = 4;
  int foundAfter = 2;

  void reset() { _low = _high = 0; }
  TrackState step(TrackState s, float confidence) {
    if (s == TrackState::Tracking) {
      _low = confidence < lostBelow ? _low + 1 : 0;
      if (_low >= lostAfter) {
        _low = _high = 0;
        return TrackState::Lost;
      }
    } else if (s == TrackState::Lost) {
      _high = confidence >= foundAbove ? _high + 1 : 0;
      if (_high >= foundAfter) {
        _low = _high = 0;
        return TrackState::Tracking;
      }
    }
    return s;
  }

 private:
  int _low = 0, _high = 0;
};

}  // namespace cuetrack
