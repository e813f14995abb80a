#include "Overlay.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "cuetrack_proto.h"

namespace cuetrack::app {
namespace {

constexpr float kDepthFarMm = 5000.f;  // colour map range: the Kinect v1's useful depth

cv::Rect toRect(const Box& b) {
  return cv::Rect(cvRound(b.x), cvRound(b.y), cvRound(b.w), cvRound(b.h));
}

// The word on the image, over a dark patch so it reads on any frame.
void label(cv::Mat& image, const char* text, cv::Point at, const cv::Scalar& colour) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &baseline);
  at.x = std::max(0, std::min(at.x, image.cols - size.width - 4));
  at.y = std::max(size.height + 4, std::min(at.y, image.rows - baseline - 2));
  cv::rectangle(image, {at.x, at.y - size.height - 3}, {at.x + size.width + 4, at.y + baseline},
                cv::Scalar(0, 0, 0), cv::FILLED);
  cv::putText(image, text, {at.x + 2, at.y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
}

}  // namespace

TrackLook trackLook(const ViewTrack& track) {
  switch (track.state) {
    case CTP_STATE_TRACKING:
      if ((track.flags & CTP_FLAG_OCCLUDED) != 0)  // where it went behind something
        return {"occluded", cv::Scalar(255, 0, 255), track.box.w > 0.f && track.box.h > 0.f};
      return {"tracking", cv::Scalar(0, 220, 0), track.box.w > 0.f && track.box.h > 0.f};
    case CTP_STATE_LOST:
      return {"lost", cv::Scalar(0, 0, 255), false};
    case CTP_STATE_SEARCHING:
      return {"searching", cv::Scalar(0, 0, 255), false};
    default:
      return {"idle", cv::Scalar(200, 200, 200), false};
  }
}

cv::Mat overlay(const cv::Mat& bgr, const cv::Mat& depth16, const ViewTrack& track,
                const char* line1, const char* line2) {
  cv::Mat colour = bgr.clone();
  const TrackLook look = trackLook(track);
  const cv::Rect box = toRect(track.box);
  if (look.drawBox) cv::rectangle(colour, box, look.colour, 2);
  // Occluded and lost say so on the image itself, not only in the strip.
  const bool occluded = (track.flags & CTP_FLAG_OCCLUDED) != 0;
  if (track.state == CTP_STATE_TRACKING && occluded && look.drawBox) {
    label(colour, look.word, {box.x, box.y - 4}, look.colour);
  } else if (track.state == CTP_STATE_LOST || track.state == CTP_STATE_SEARCHING) {
    label(colour, "target lost", {4, 20}, look.colour);
  }
  cv::Mat image = colour;
  if (!depth16.empty()) {
    cv::Mat d8, depthColour;
    depth16.convertTo(d8, CV_8U, 255.0 / kDepthFarMm);
    cv::applyColorMap(d8, depthColour, cv::COLORMAP_JET);
    depthColour.setTo(cv::Scalar(0, 0, 0), depth16 == 0);  // no measurement: black
    if (look.drawBox) cv::rectangle(depthColour, box, cv::Scalar(255, 255, 255), 2);
    cv::hconcat(colour, depthColour, image);
  }
  cv::Mat canvas(image.rows + kStripPx, image.cols, CV_8UC3, cv::Scalar(32, 32, 32));
  image.copyTo(canvas(cv::Rect(0, 0, image.cols, image.rows)));
  cv::putText(canvas, line1, {6, image.rows + 17}, cv::FONT_HERSHEY_SIMPLEX, 0.5, look.colour, 1,
              cv::LINE_AA);
  cv::putText(canvas, line2, {6, image.rows + 37}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
  return canvas;
}

}  // namespace cuetrack::app
