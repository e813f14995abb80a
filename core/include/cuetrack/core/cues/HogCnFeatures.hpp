// The background-aware filter's features (BackgroundAwareFilter.hpp), as the hand-crafted
// trackers that beat CSRT use them (ECO-HC, STRCF, BACF): a window of the colour image
// resampled to kFftSide x kFftSide cells of kCellPx x kCellPx samples, and per cell
//   - 31 fHOG channels (Felzenszwalb et al. 2010): 18 contrast-sensitive orientations, 9
//     contrast-insensitive ones, each normalised by the four 2 x 2 blocks around the cell
//     and clipped at 0.2, and 4 texture channels (the clipped energy in each block): the
//     target's outline and texture, robust to brightness;
//   - 10 colour names (ColourNames.hpp): what the target's colours are called, robust to
//     shading, which gradients do not see;
//   - the mean gray level, centred: a smooth or tiny target's blob.
// Resampling to a fixed grid keeps memory and cost fixed whatever the target's size and
// gives a target of a few pixels several cells. One channel is a plane of kFftSize
// floats, row by row. Plain float code in one order: the same bits on every ISA.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack {

class HogCnFeatures {
 public:
  static constexpr int kOrientations = 9;
  static constexpr int kSignedChannel = 0;                                     // 18
  static constexpr int kUnsignedChannel = kSignedChannel + 2 * kOrientations;  // 9
  static constexpr int kTextureChannel = kUnsignedChannel + kOrientations;     // 4
  static constexpr int kNameChannel = kTextureChannel + 4;                     // 10
  static constexpr int kGrayChannel = kNameChannel + 10;                       // 1
  static constexpr int kChannels = kGrayChannel + 1;                           // 42
  // fHOG's 4 px cells on a window resampled to kSamples pixels a side.
  static constexpr int kCellPx = 4;
  static constexpr int kSamples = kFftSide * kCellPx;  // 128

  // The features of window `win` of `rgb` (clamped at the image's border) into
  // out[kChannels][kFftSize]. False for an empty image or window.
  bool extract(const RgbView& rgb, const Box& win, float (*out)[kFftSize]);

  // After extract(): the window's samples, row by row (kSamples x kSamples), as colour
  // (for the foreground model, which reads the same pixels the filter does).
  const Rgb8* samples() const { return _rgb; }

 private:
  Rgb8 _rgb[kSamples * kSamples];
  float _gray[kSamples * kSamples];
  float _mag[kSamples * kSamples];
  uint8_t _bin[kSamples * kSamples];         // signed orientation, 0..17
  float _hist[kFftSize][2 * kOrientations];  // signed, cell by cell
  float _energy[kFftSize];                   // of the unsigned histogram
  float _blockInv[kFftSize];                 // 1 / norm of the block whose top-left is the cell
};

}  // namespace cuetrack
