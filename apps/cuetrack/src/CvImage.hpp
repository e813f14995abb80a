// The frame's colour as an OpenCV image (BGR, a copy): what every picture the app draws
// or writes starts from. Host builds only.
#pragma once

#include <opencv2/core.hpp>

#include "cuetrack/core/base/Frame.hpp"

namespace cuetrack::app {

cv::Mat toBgr(const RgbView& rgb);

}  // namespace cuetrack::app
