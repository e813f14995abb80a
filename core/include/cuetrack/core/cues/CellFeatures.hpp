// The correlation filter's features (CorrelationFilter.hpp): a window of the colour image
// resampled to kFftSide x kFftSide cells of kCellPx x kCellPx samples, and per cell
//   - 9 histogram-of-oriented-gradient channels (unsigned orientation, hard-binned,
//     magnitude-weighted,
//     each cell normalised by the gradient energy of the four 2 x 2 blocks around it and
//     clipped, as in Felzenszwalb's HOG: what the target's outline and texture look like,
//     robust to brightness);
//   - its mean gray level (centred on mid-gray): a smooth or small target's blob;
//   - two opponent-colour means (r - g, (r + g) / 2 - b): what gray and gradients do not
//     tell apart.
// Resampling to a fixed grid keeps memory and cost fixed whatever the target's size, and
// upsamples a target of a few pixels. One channel is a plane of kFftSize floats, row by
// row. Plain float code in one order: the same bits on every ISA.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack {

class CellFeatures {
 public:
  static constexpr int kOrientations = 9;
  // Also 18 contrast-sensitive (signed) orientation channels, before the unsigned ones
  // (fHOG's): off, as they gave no gain for 2.5 times the filter's cost (the filter alone
  // on 5 real videos: 46.1 with them, 47.6 without).
  static constexpr bool kSigned = false;
  static constexpr int kUnsignedChannel = kSigned ? 2 * kOrientations : 0;
  static constexpr int kGrayChannel = kUnsignedChannel + kOrientations;
  static constexpr int kColourChannel = kGrayChannel + 1;  // and the next
  static constexpr int kChannels = kColourChannel + 2;     // 12 (30 with kSigned)
  static constexpr int kCellPx = 2;                        // samples per cell side
  static constexpr int kSamples = kFftSide * kCellPx;      // samples per window side (64)
  static constexpr int kPlanes = kChannels;

  // The features of window `win` of `rgb` (clamped at the image's border) into
  // out[kChannels][kFftSize]. False for an empty image or window.
  bool extract(const RgbView& rgb, const Box& win, float (*out)[kFftSize]);

 private:
  // extract()'s steps after sampling: the samples' gradients; the cells' histograms, gray
  // and colour into out; the histograms normalised by their blocks into out.
  void gradients();
  void cells(float (*out)[kFftSize]);
  void normalise(float (*out)[kFftSize]);

  // Scratch: the window's samples (gray, two colour opponents), their gradients'
  // magnitude and orientation bin, the cells' raw orientation histograms, their gradient
  // energy and the inverse norm of each 2 x 2 block.
  float _gray[kSamples * kSamples];
  float _ca[kSamples * kSamples];
  float _cb[kSamples * kSamples];
  float _dx[kSamples * kSamples];
  float _dy[kSamples * kSamples];
  float _mag[kSamples * kSamples];
  uint8_t _bin[kSamples * kSamples];
  float _hist[kFftSize][2 * kOrientations];  // signed, cell by cell
  float _unsigned[kFftSize][kOrientations];
  float _energy[kFftSize];
  float _blockInv[kFftSize];
};

}  // namespace cuetrack
