// The picker on OpenCV images, for whichever thread owns highgui: the live window's
// thread with --show (re-selecting with r, --select), the caller's without. Host only.
#pragma once

#include <cstddef>
#include <opencv2/core.hpp>
#include <opencv2/highgui.hpp>

#include "cuetrack/core/Geometry.hpp"

namespace cuetrack::app {

// No toolbar (Qt's zoom buttons): the image starts at the window's corner, 1:1.
inline constexpr int kWindowFlags = cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL;

// cv::selectROI in window, with its instructions sent to stderr (stdout carries tracks).
cv::Rect selectRoi(const char* window, const cv::Mat& image);

// A window of its own on bgr, the drag, the box. False + one line in err on cancel.
bool pickOn(const cv::Mat& bgr, Box* out, char* err, size_t errLen);

}  // namespace cuetrack::app
