// --snapshot: the first frame as a PNG with a pixel grid, for reading a box off it on a
// board without a display.
#pragma once

#include <cstddef>

#include "cuetrack/core/base/Frame.hpp"

namespace cuetrack::app {

// Writes frame as a PNG with a labelled pixel grid every kSnapshotGridPx, so a box can be
// read off it on a machine without a display. The labels are multiplied by x/yLabelScale:
// a frame scaled down from a larger source is labelled in the source's pixels, which
// --box takes. False + one line in err.
inline constexpr int kSnapshotGridPx = 40;
bool writeSnapshot(const Frame& frame, const char* path, char* err, size_t errLen,
                   float xLabelScale = 1.f, float yLabelScale = 1.f);

}  // namespace cuetrack::app
