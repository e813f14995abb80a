// --select: the user drags the target's box on the first frame.
#pragma once

#include <cstddef>

#include "cuetrack/core/Frame.hpp"
#include "cuetrack/core/Geometry.hpp"

namespace cuetrack::app {

// Shows frame and lets the user drag a box (cv::selectROI; Enter/space accepts, c or Esc
// cancels). False + one line in err on cancel or an empty box.
bool pickBox(const Frame& frame, Box* out, char* err, size_t errLen);

}  // namespace cuetrack::app
