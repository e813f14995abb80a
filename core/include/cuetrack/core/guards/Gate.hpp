// The two small decisions around learning: whether to learn from this frame
// (the paper's update gate) and, beyond the paper, whether the target is lost.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

// Learn only when the classifier is confident at the estimate and the particle
// cloud agrees with it (weighted mean overlap of particles with the estimate).
struct UpdateGate {
  float minConfidence = tuning::kLearnConfidence;
  float minConcentration = tuning::kLearnConcentration;
  bool open(float confidence, float concentration, TrackState state) const {
    return state == TrackState::Tracking && confidence >= minConfidence &&
           concentration >= minConcentration;
  }
};

// Lost after `lostAfter` consecutive frames with confidence below `lostBelow`;
// found again after `foundAfter` consecutive frames at or above the found threshold:
// `foundAbove`, or, if higher, the confidence the target typically had while tracked
// (a running mean over tracked frames at or above `foundAbove`) less `foundMargin`, so a
// look-alike that scores well below the real target is not taken for it. A target
// found again is on probation for `probationFrames` more frames: one frame below
// `foundAbove` then and it is lost again, and the tracker does not learn until the
// probation is over.
class LostDetector {
 public:
  float lostBelow = tuning::lost::kLostBelow;
  float foundAbove = tuning::lost::kFoundAbove;
  int lostAfter = tuning::lost::kLostAfter;
  int foundAfter = tuning::lost::kFoundAfter;
  int probationFrames = tuning::lost::kProbationFrames;
  float foundMargin = tuning::lost::kFoundMargin;
  float typicalRate = tuning::lost::kTypicalRate;  // weight of the latest frame (once warm)

  void reset() {
    _low = _high = _probation = _typicalCount = 0;
    _typical = 0.f;
  }
  bool onProbation() const { return _probation > 0; }
  float foundThreshold() const {
    return _typical - foundMargin > foundAbove ? _typical - foundMargin : foundAbove;
  }
  // stillSeen: another cue still sees the target at the estimate this frame (the
  // correlation filter, 3D); a low confidence then does not count towards "lost": the
  // target is lost when the cues agree it is gone, not when the classifier alone dips
  // (a spinning target, a twin passing). It changes neither probation nor "found".
  TrackState step(TrackState s, float confidence, bool stillSeen = false) {
    const float found = foundThreshold();
    if (s == TrackState::Tracking && _probation > 0) {
      --_probation;
      if (confidence < foundAbove) {
        _low = _high = _probation = 0;
        return TrackState::Lost;
      }
      return s;
    }
    if (s == TrackState::Tracking) {
      if (confidence >= foundAbove) {
        // The plain mean until 1 / typicalRate frames are in, then the running mean: from
        // 0 the running mean would sit low for ~20 frames, and a target lost that early
        // could be "found" on a look-alike the margin is there to reject.
        if (_typicalCount < 1000) ++_typicalCount;
        const float rate = 1.f / static_cast<float>(_typicalCount);
        _typical += (rate > typicalRate ? rate : typicalRate) * (confidence - _typical);
      }
      _low = confidence < lostBelow && !stillSeen ? _low + 1 : 0;
      if (_low >= lostAfter) {
        _low = _high = 0;
        return TrackState::Lost;
      }
    } else if (s == TrackState::Lost) {
      _high = confidence >= found ? _high + 1 : 0;
      if (_high >= foundAfter) {
        _low = _high = 0;
        _probation = probationFrames;
        return TrackState::Tracking;
      }
    }
    return s;
  }

 private:
  int _low = 0, _high = 0, _probation = 0;
  int _typicalCount = 0;  // tracked frames in _typical
  float _typical = 0.f;   // running mean of the tracked confidence
};

}  // namespace cuetrack
