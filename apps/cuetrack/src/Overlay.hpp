// The picture the window shows and the video records: the frame with the track drawn,
// the depth colour-mapped beside it, and two lines of text in a strip under them.
// Host builds only.
#pragma once

#include <opencv2/core.hpp>

#include "ViewTrack.hpp"

namespace cuetrack::app {

inline constexpr int kStripPx = 44;  // status text under the image

// bgr: the frame; depth16: its depth [mm] at the same size, or empty for none.
cv::Mat overlay(const cv::Mat& bgr, const cv::Mat& depth16, const ViewTrack& track,
                const char* line1, const char* line2);

}  // namespace cuetrack::app
