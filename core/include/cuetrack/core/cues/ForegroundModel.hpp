// Which pixels of the box are the target (issue 53's foreground): colour histograms of
// the target's box and of its surround give each colour a likelihood of being target,
// P(target | colour) = p_t / (p_t + p_s) with p_t, p_s the colour's share of the target's
// and of the surround's pixels (Staple, Bertinetto et al. 2016; CSR-DCF's colour prior).
// The background-aware filter uses it as its mask: the filter learns only the target's
// cells of the box, not the background that fills the rest of it (CSR-DCF's spatial
// reliability). (Staple's use, a colour response merged into the filter's, did worse
// with the mask and without it: docs/experiments.md.)
// It works on the filter's own samples (HogCnFeatures::samples(): the window resampled
// to kSide x kSide), so it costs no second read of the image. Histograms of
// kBins^3 colours, learnt as running averages.
#pragma once

#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack {

class ForegroundModel {
 public:
  static constexpr int kBinsPerChannel = 16;  // 4096 colours: a small target still fills them
  static constexpr int kColours = kBinsPerChannel * kBinsPerChannel * kBinsPerChannel;
  static constexpr int kSide = 128;  // samples a window side (HogCnFeatures)
  static constexpr int kCellPx = kSide / kFftSide;

  // The target's box in the window's samples: [x0, x1) x [y0, y1).
  struct Rect {
    int x0, y0, x1, y1;
  };

  // New histograms from samples[kSide * kSide] with the target in `target`.
  void reset(const Rgb8* samples, const Rect& target);
  // Blends the histograms of these samples in at `rate`.
  void learn(const Rgb8* samples, const Rect& target, float rate);
  bool ready() const { return _ready; }

  // The likelihood of every sample into map[kSide * kSide].
  void likelihood(const Rgb8* samples, float* map) const;
  // The mean likelihood of each cell's samples, for a kFftSide^2 grid.
  static void cellMeans(const float* map, float* cells);

 private:
  void histograms(const Rgb8* samples, const Rect& target, float* fg, float* bg) const;

  float _fg[kColours], _bg[kColours];        // the learnt shares
  float _newFg[kColours], _newBg[kColours];  // scratch
  bool _ready = false;
};

}  // namespace cuetrack
