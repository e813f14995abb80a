#include "Overlay.hpp"

#include <opencv2/imgproc.hpp>

#include "cuetrack_proto.h"

namespace cuetrack::app {
namespace {

constexpr float kDepthFarMm = 5000.f;  // colour map range: the Kinect v1's useful depth

cv::Scalar stateColour(uint8_t state) {
  switch (state) {
    case CTP_STATE_TRACKING:
      return {0, 220, 0};
    case CTP_STATE_LOST:
      return {0, 0, 255};
    default:
      return {0, 200, 255};  // searching, idle
  }
}

cv::Rect toRect(const Box& b) {
  return cv::Rect(cvRound(b.x), cvRound(b.y), cvRound(b.w), cvRound(b.h));
}

}  // namespace

cv::Mat overlay(const cv::Mat& bgr, const cv::Mat& depth16, const ViewTrack& track,
                const char* line1, const char* line2) {
  cv::Mat colour = bgr.clone();
  const cv::Scalar c = stateColour(track.state);
  const bool hasBox = track.state != CTP_STATE_IDLE && track.box.w > 0.f;
  if (hasBox) cv::rectangle(colour, toRect(track.box), c, 2);
  cv::Mat image = colour;
  if (!depth16.empty()) {
    cv::Mat d8, depthColour;
    depth16.convertTo(d8, CV_8U, 255.0 / kDepthFarMm);
    cv::applyColorMap(d8, depthColour, cv::COLORMAP_JET);
    depthColour.setTo(cv::Scalar(0, 0, 0), depth16 == 0);  // no measurement: black
    if (hasBox) cv::rectangle(depthColour, toRect(track.box), cv::Scalar(255, 255, 255), 2);
    cv::hconcat(colour, depthColour, image);
  }
  cv::Mat canvas(image.rows + kStripPx, image.cols, CV_8UC3, cv::Scalar(32, 32, 32));
  image.copyTo(canvas(cv::Rect(0, 0, image.cols, image.rows)));
  cv::putText(canvas, line1, {6, image.rows + 17}, cv::FONT_HERSHEY_SIMPLEX, 0.5, c, 1,
              cv::LINE_AA);
  cv::putText(canvas, line2, {6, image.rows + 37}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
  return canvas;
}

}  // namespace cuetrack::app
