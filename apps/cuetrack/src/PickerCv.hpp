// The picker on OpenCV images, for whichever thread owns highgui: the live window's
// thread with --show (re-selecting with r, --select), the caller's without. Host only.
#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <opencv2/highgui.hpp>

#include "Picker.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

// No toolbar (Qt's zoom buttons): the image starts at the window's corner, 1:1.
inline constexpr int kWindowFlags = cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL;

// A mouse drag in window (already created) on image: our own loop rather than
// cv::selectROI, whose loop cannot be left but by a key. Polls stop() every 20 ms.
// Picked: *out is the box dragged, inside the image.
PickResult selectRoi(const char* window, const cv::Mat& image, bool (*stop)(), cv::Rect* out);

// A window of its own on bgr, the drag, the box; err says why there is none.
PickResult pickOn(const cv::Mat& bgr, bool (*stop)(), Box* out, char* err, size_t errLen);

}  // namespace cuetrack::app
