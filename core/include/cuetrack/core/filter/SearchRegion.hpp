// The region of the image a frame tabulates (IntegralChannels::compute): what the
// particles' windows touch, grown by kRoiMarginSides of their mean size on every side for
// the negatives sampled around the estimate, with the appearance cue's search region
// when it searches around the last estimate; the whole image when the cue scans for a
// lost target, or when the region would be degenerate.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Span.hpp"

namespace cuetrack {

struct SearchRegion {
  // windows: the particles' windows (empty ones are skipped, yet count in the mean);
  // cueRegion: the cue's region (nullptr: none); wholeImage: the lost scan.
  static PixelRect of(Span<const Box> windows, const Box* cueRegion, bool wholeImage, int imageW,
                      int imageH);
};

}  // namespace cuetrack
