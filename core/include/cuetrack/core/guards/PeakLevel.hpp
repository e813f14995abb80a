// How strongly the correlation filter answers on its own target (beyond the paper; with
// `lostDetection`, 3D): a running mean of its peak around the estimate on the frames
// learnt. A target found again must reach a fraction of it while on probation ("found"
// only when it is the target): the classifier alone confirmed a patch of wall beside a
// target hidden by an occluder, where the filter answered at a tenth of its usual peak
// (synthetic `occlusion`, docs/algorithm.md). While tracking, a peak that still reaches
// that fraction on the estimate keeps a low classifier frame from counting towards
// "lost" (LostDetector: lost only when the cues agree).
#pragma once

namespace cuetrack {

class PeakLevel {
 public:
  // Half the target's usual peak: a target blurred by a jump still reaches about that,
  // clutter mostly not. Set before measuring, not tuned.
  static constexpr float kFoundFraction = 0.5f;
  // About 10 frames' memory, as the appearance models learn.
  static constexpr float kRate = 0.1f;

  void reset() {
    _mean = 0.f;
    _seen = false;
  }
  // The filter's peak around the estimate on a frame learnt.
  void learnt(float peak) {
    if (!(peak > 0.f)) return;
    _mean = _seen ? _mean + kRate * (peak - _mean) : peak;
    _seen = true;
  }
  float mean() const { return _mean; }
  // Whether a peak is too low for the target (never before a frame was learnt).
  bool unlike(float peak) const { return _seen && peak < kFoundFraction * _mean; }
  // Whether a peak answers like the target (never before a frame was learnt).
  bool like(float peak) const { return _seen && !unlike(peak); }

 private:
  float _mean = 0.f;
  bool _seen = false;
};

}  // namespace cuetrack
