// The tracker's dense appearance cue (beyond the paper; `correlationCue`): a
// discriminative correlation filter on HOG, gray and colour cells (CellFeatures), learnt
// in the Fourier domain with a running average, and searched at three scales.
//
// Model (multi-channel linear DCF, as in MOSSE / DSST / KCF's linear kernel): for the
// features x_l of a window kPadding times the target, cosine-windowed, and a Gaussian
// label y peaked at zero shift,
//     A_l = conj(X_l) Y,   B = sum_l |X_l|^2        (learnt: (1 - rate) old + rate new)
//     response(z) = F^-1( sum_l A_l Z_l / (B + lambda) ),
// the least-squares filter whose correlation with x is y. One search is 12 channels'
// transforms and one inverse on a 32 x 32 grid, whatever the target's size.
//
// Why: the boosted classifier scores windows the particles propose; where the target
// jumps or turns, the cloud falls behind and the classifier, learning from its own
// estimates, drifts. A correlation filter scores every shift of a padded window at once,
// with the context around the target as its negatives, and says how much bigger or
// smaller the target has become. Its response is a proposal (particles drawn at its
// peak, at its scale) and a second term of the particles' weights.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/cues/CellFeatures.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack {

class CorrelationFilter {
 public:
  static constexpr int kChannels = CellFeatures::kChannels;
  // The window read around a target: kPadding times its sides (the context the filter
  // learns as negatives, and the reach of a search: shifts of up to kPadding / 2 sides).
  // 3 rather than KCF's 2.5: a target that jumps (a face skipping rope, a shaken camera)
  // stays further from the cosine window's edge (real videos 49.1 -> 51.3, 3 seeds).
  static constexpr float kPadding = 3.0f;
  static constexpr int kScales = 3;           // searched: 1 / kScaleStep, 1, kScaleStep
  static constexpr float kNoResponse = -1.f;  // at(): outside the map

  CorrelationFilter();

  // The box a search reads around the window `around`, with the target's box at any
  // shift found (the classifier scores the peak's box: the tables must cover it).
  static Box region(const Box& around) {
    constexpr float r = 0.5f * ((kPadding + 1.f) * tuning::dcf::kScaleStep - 1.f);
    return Box{around.x - r * around.w, around.y - r * around.h, (1.f + 2.f * r) * around.w,
               (1.f + 2.f * r) * around.h};
  }

  // A new filter from target box `target` (false for an empty image or box).
  bool reset(const RgbView& rgb, const Box& target);
  // Blends the filter learnt at box `target` in at `rate` (0..1).
  void learn(const RgbView& rgb, const Box& target, float rate);
  // The response at every shift of the window around box `around`, at three scales when
  // `scales` (the best kept), else at its own size. False without a filter.
  bool search(const RgbView& rgb, const Box& around, bool scales);
  bool ready() const { return _ready; }

  // After search(): the peak's response (1 where the filter sees what it learnt), its box
  // (the target's, at the scale found) and how far it stands out of the map (peak to
  // sidelobe ratio: (peak - mean) / spread).
  float peak() const { return _peak; }
  Box peakBox() const { return _peakBox; }
  float sharpness() const { return _psr; }
  // The response at a target centred at (u, v) [px] over the peak's (so 1 at the peak),
  // bilinear between cells; kNoResponse outside the searched window.
  float at(float u, float v) const;

 private:
  // Features of box `target`'s window, cosine-windowed and transformed into _zRe/_zIm.
  bool transformed(const RgbView& rgb, const Box& target);
  // The response of _zRe/_zIm into `map`; its peak's value and cell.
  void respond(float* map, float* peak, int* peakAt);

  CellFeatures _features;
  float _cosine[kFftSize];                                     // the cosine (Hann) window
  float _yRe[kFftSize], _yIm[kFftSize];                        // the label's transform
  float _aRe[kChannels][kFftSize], _aIm[kChannels][kFftSize];  // the filter's numerator
  float _b[kFftSize];                                          // ... and denominator
  float _x[kChannels][kFftSize];                               // features (scratch)
  float _zRe[kChannels][kFftSize], _zIm[kChannels][kFftSize];  // their transforms (scratch)
  float _map[kFftSize], _tryMap[kFftSize], _respIm[kFftSize];  // responses (scratch)
  bool _ready = false;
  // The last search: the window's centre and cell size [px], the peak.
  float _cx = 0.f, _cy = 0.f, _cellW = 1.f, _cellH = 1.f;
  float _peak = kNoResponse, _psr = 0.f;
  Box _peakBox{};
  bool _searched = false;
};

}  // namespace cuetrack
