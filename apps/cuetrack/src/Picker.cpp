// The picker on OpenCV's highgui: a drag with the mouse, in a loop of our own that polls
// the stop flag (cv::selectROI's loop would ignore Ctrl-C until a key came).
#include "Picker.hpp"

#include <algorithm>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "CvImage.hpp"
#include "PickerCv.hpp"

namespace cuetrack::app {
namespace {

constexpr int kPollMs = 20;  // between looks at the stop flag and the keys

// The drag so far, filled by highgui's mouse callback on the picker's thread.
struct Drag {
  cv::Point from, to;
  bool dragging = false, dragged = false;
};

void onMouse(int event, int x, int y, int /*flags*/, void* p) {
  Drag& d = *static_cast<Drag*>(p);
  if (event == cv::EVENT_LBUTTONDOWN) {
    d.from = d.to = {x, y};
    d.dragging = true;
    d.dragged = false;
  } else if (event == cv::EVENT_MOUSEMOVE && d.dragging) {
    d.to = {x, y};
  } else if (event == cv::EVENT_LBUTTONUP && d.dragging) {
    d.to = {x, y};
    d.dragging = false;
    d.dragged = true;
  }
}

cv::Rect dragRect(const Drag& d, const cv::Mat& image) {
  const cv::Rect r(cv::Point(std::min(d.from.x, d.to.x), std::min(d.from.y, d.to.y)),
                   cv::Point(std::max(d.from.x, d.to.x), std::max(d.from.y, d.to.y)));
  return r & cv::Rect(0, 0, image.cols, image.rows);
}

}  // namespace

PickResult selectRoi(const char* window, const cv::Mat& image, bool (*stop)(), cv::Rect* out) {
  Drag drag;
  cv::setMouseCallback(window, onMouse, &drag);
  PickResult result = PickResult::Cancelled;
  *out = cv::Rect();
  for (;;) {
    if (stop && stop()) {
      result = PickResult::Interrupted;
      break;
    }
    cv::Mat shown = image.clone();
    const cv::Rect r = dragRect(drag, image);
    if ((drag.dragging || drag.dragged) && r.area() > 0)
      cv::rectangle(shown, r, cv::Scalar(255, 0, 0), 2);
    cv::putText(shown, "drag a box, Enter or space accepts, c or Esc cancels", {6, image.rows - 8},
                cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    cv::imshow(window, shown);
    const int key = cv::waitKey(kPollMs);  // the mouse events come in here too
    if (key == 13 || key == 10 || key == ' ') {
      const cv::Rect dragged = dragRect(drag, image);
      if (dragged.area() > 0) {
        *out = dragged;
        result = PickResult::Picked;
      }
      break;
    }
    if (key == 27 || key == 'c' || key == 'C') break;
    if (cv::getWindowProperty(window, cv::WND_PROP_VISIBLE) < 1) break;  // closed
  }
  cv::setMouseCallback(window, nullptr, nullptr);  // drag dies with this frame
  return result;
}

PickResult pickOn(const cv::Mat& bgr, bool (*stop)(), Box* out, char* err, size_t errLen) {
  constexpr const char* kPickWindow = "cuetrack: drag a box around the target, Enter to accept";
  cv::namedWindow(kPickWindow, kWindowFlags);
  cv::Rect r;
  const PickResult result = selectRoi(kPickWindow, bgr, stop, &r);
  cv::destroyWindow(kPickWindow);
  cv::waitKey(1);  // lets the window close before the run goes on
  if (result == PickResult::Interrupted) {
    std::snprintf(err, errLen, "--select: interrupted before a box was picked");
  } else if (result == PickResult::Cancelled) {
    std::snprintf(err, errLen, "--select: no box was drawn (cancelled)");
  } else {
    *out = Box{static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.width),
               static_cast<float>(r.height)};
  }
  return result;
}

PickResult pickBox(const Frame& frame, bool (*stop)(), Box* out, char* err, size_t errLen) {
  return pickOn(toBgr(frame.rgb), stop, out, err, errLen);
}

}  // namespace cuetrack::app
