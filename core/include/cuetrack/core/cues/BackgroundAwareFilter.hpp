// A background-aware correlation filter (BACF: Kiani Galoogahi, Fagg, Lucey, ICCV 2017),
// the appearance model of the `dcf` configuration (FilterTracker) and the answer to "the
// model learns the box, not the target" (issue 53).
//
// A plain DCF (CorrelationFilter) learns from the circular shifts of one cosine-windowed
// patch: most of its "negatives" are wrapped copies of the target, so it cannot use a
// window much larger than the target, and whatever fills the box is learnt as target.
// BACF keeps the filter the size of the target (cropped by P) but trains it against
// every real shift of a window kPadding times larger, so the background around the
// target is what it learns to reject:
//     min_h  1/2 || y - sum_k (P^T h_k) * x_k ||^2 + lambda/2 sum_k ||h_k||^2
// solved by ADMM with g = P^T h split off (dual l, penalty mu), each step closed form:
//   g: per frequency, (x x^H + mu I) g = x conj(y) + mu h - l  (Sherman-Morrison: O(K))
//   h: h = P(F^-1 (mu g + l)) / (mu + lambda): the target-sized crop, one inverse and one
//      forward transform a channel
//   l: l += mu (g - h);  mu = min(beta mu, mu_max).
// The model is the running average of the windows' transforms; the filter is solved from
// it anew on each learnt frame with a fixed number of iterations (the same bits on every
// ISA). Search: response = F^-1(sum_k conj(g_k) z_k) over the window's every shift.
//
// Features: HogCnFeatures (fHOG 31, colour names 10, gray 1) on a kFftSide^2 grid. The
// window is square (kPadding sqrt(w h) a side), so the cells are square and fHOG's
// orientations mean what they say whatever the target's aspect.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/cues/ForegroundModel.hpp"
#include "cuetrack/core/cues/HogCnFeatures.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack {

class BackgroundAwareFilter {
 public:
  static constexpr int kChannels = HogCnFeatures::kChannels;
  static_assert(kChannels % 2 == 0, "channels are transformed in pairs");
  // The window's side over the target's (geometric mean of its sides): BACF's 5 on a
  // 50-cell grid puts 10 cells across the target; on our 32-cell grid 4 puts 8.
  static constexpr float kPadding = 4.f;
  // The foreground model's learning rate (Staple's).
  static constexpr float kColourRate = 0.04f;

  // The answer of a search: the peak's response (about 1 on what was learnt), the
  // target's box moved to it (the same size as the box searched), the peak to sidelobe
  // ratio of the map; valid false without a filter or for an empty box.
  struct Answer {
    bool valid = false;
    float peak = 0.f;
    float psr = 0.f;
    Box box{};
  };

  BackgroundAwareFilter();

  // The square window read around target box `target`.
  static Box window(const Box& target);

  // A new filter for target box `target` (false for an empty image or box).
  bool reset(const RgbView& rgb, const Box& target);
  // Blends the window around `target` into the model at `rate` (0..1) and solves the
  // filter anew.
  void learn(const RgbView& rgb, const Box& target, float rate);
  // Every shift of the window around `target` (its size is the scale searched).
  Answer search(const RgbView& rgb, const Box& target);
  bool ready() const { return _ready; }

 private:
  bool transformed(const RgbView& rgb, const Box& target);  // into _zRe/_zIm
  void solve();                                             // ADMM: _model -> _g
  void measureSelfPeak();                                   // _selfPeak from _g and _model
  // The target's box in the window's samples.
  ForegroundModel::Rect targetSamples() const;
  // The mask P: the target's box, less its cells that the colours say are background.
  void updateMask();

  ForegroundModel _colour;
  float _likelihood[ForegroundModel::kSide * ForegroundModel::kSide];
  float _cells[kFftSize];
  float _selfPeak = 1.f;  // the filter's response on its own model: the map's scale
  int _boxX0 = 0, _boxX1 = 0, _boxY0 = 0, _boxY1 = 0;  // the target's cells in the window

  HogCnFeatures _features;
  float _cosine[kFftSize];
  float _yRe[kFftSize], _yIm[kFftSize];  // the label's transform
  float _mask[kFftSize];                 // P: 1 on the target's cells, about the centre
  float _x[kChannels][kFftSize];         // features (scratch)
  float _zRe[kChannels][kFftSize], _zIm[kChannels][kFftSize];  // their transforms
  float _mRe[kChannels][kFftSize], _mIm[kChannels][kFftSize];  // the model
  float _gRe[kChannels][kFftSize], _gIm[kChannels][kFftSize];  // the filter
  float _hRe[kChannels][kFftSize], _hIm[kChannels][kFftSize];  // ADMM: its crop
  float _uRe[kChannels][kFftSize], _uIm[kChannels][kFftSize];  // ... the dual (l)
  float _sxx[kFftSize], _sRe[kFftSize], _sIm[kFftSize];        // ... per-frequency sums
  float _map[kFftSize], _mapIm[kFftSize];                      // a response
  bool _ready = false;
};

}  // namespace cuetrack
