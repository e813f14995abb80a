// The picker on OpenCV's highgui (cv::selectROI).
#include "Picker.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "CvImage.hpp"
#include "PickerCv.hpp"

namespace cuetrack::app {

// cv::selectROI prints its instructions on stdout, which carries the track lines: they
// go to stderr instead.
cv::Rect selectRoi(const char* window, const cv::Mat& image) {
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  if (saved >= 0) dup2(STDERR_FILENO, STDOUT_FILENO);
  const cv::Rect r = cv::selectROI(window, image, true, false);
  std::cout.flush();
  std::fflush(stdout);
  if (saved >= 0) {
    dup2(saved, STDOUT_FILENO);
    close(saved);
  }
  return r;
}

// The picker's window and drag, on the thread that owns highgui.
bool pickOn(const cv::Mat& bgr, Box* out, char* err, size_t errLen) {
  constexpr const char* kPickWindow = "cuetrack: drag a box around the target, Enter to accept";
  cv::namedWindow(kPickWindow, kWindowFlags);
  const cv::Rect r = selectRoi(kPickWindow, bgr);
  cv::destroyWindow(kPickWindow);
  cv::waitKey(1);  // lets the window close before the run goes on
  if (r.width <= 0 || r.height <= 0) {
    std::snprintf(err, errLen, "--select: no box was drawn (cancelled)");
    return false;
  }
  *out = Box{static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.width),
             static_cast<float>(r.height)};
  return true;
}

bool pickBox(const Frame& frame, Box* out, char* err, size_t errLen) {
  return pickOn(toBgr(frame.rgb), out, err, errLen);
}

}  // namespace cuetrack::app
