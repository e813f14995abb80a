// A short video written with OpenCV for the video-size tests: a textured rectangle moving
// over a smooth background, at any frame size, with its true box per frame in the video's
// own pixels. Host builds with OpenCV only (the tests that include it link opencv_videoio).
#pragma once

#include <cstdint>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::test {

// The rectangle's box in frame i of a width x height video: a sixth of the width wide,
// starting right of the centre (so its x is past 640 in a large video), moving right
// and down by about a hundredth of the width per frame.
inline Box movingRectBox(int i, int width, int height) {
  const float w = static_cast<float>(width) / 6.f, h = static_cast<float>(height) / 4.f;
  const float step = static_cast<float>(width) / 120.f;
  return Box{static_cast<float>(width) * 0.55f + step * i,
             static_cast<float>(height) * 0.3f + 0.4f * step * i, w, h};
}

// Writes `frames` frames to path with the given FourCC ('M','J','P','G' for .avi,
// 'm','p','4','v' for .mp4); false when this OpenCV cannot write that container/codec.
inline bool writeMovingRectVideo(const std::string& path, int fourcc, int width, int height,
                                 int frames, double fps = 25.0) {
  cv::VideoWriter writer;
  if (!writer.open(path, cv::CAP_FFMPEG, fourcc, fps, cv::Size(width, height)) ||
      !writer.isOpened())
    return false;
  // The target's texture: 12x9 cells of fixed pseudo-random colours, stretched to its box.
  cv::Mat cells(9, 12, CV_8UC3);
  uint32_t s = 12345u;
  for (int y = 0; y < cells.rows; ++y)
    for (int x = 0; x < cells.cols; ++x) {
      s = s * 1664525u + 1013904223u;
      cells.at<cv::Vec3b>(y, x) = cv::Vec3b(
          static_cast<uchar>(s >> 24), static_cast<uchar>(s >> 16), static_cast<uchar>(s >> 8));
    }
  cv::Mat background(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      background.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<uchar>(60 + 40 * x / width), static_cast<uchar>(90),
                    static_cast<uchar>(70 + 50 * y / height));
  cv::Mat frame, patch;
  for (int i = 0; i < frames; ++i) {
    background.copyTo(frame);
    const Box b = movingRectBox(i, width, height);
    const cv::Rect r(cvRound(b.x), cvRound(b.y), cvRound(b.w), cvRound(b.h));
    cv::resize(cells, patch, r.size(), 0, 0, cv::INTER_NEAREST);
    const cv::Rect inside = r & cv::Rect(0, 0, width, height);  // it leaves after ~40 frames
    if (!inside.empty()) patch(inside - r.tl()).copyTo(frame(inside));
    writer.write(frame);
  }
  writer.release();
  return true;
}

// The boxes as an OTB ground-truth file (x,y,w,h, 1-based pixels), one line per frame.
inline std::string otbGroundTruth(int frames, int width, int height) {
  std::string text;
  char line[96];
  for (int i = 0; i < frames; ++i) {
    const Box b = movingRectBox(i, width, height);
    std::snprintf(line, sizeof line, "%d,%d,%d,%d\n", cvRound(b.x) + 1, cvRound(b.y) + 1,
                  cvRound(b.w), cvRound(b.h));
    text += line;
  }
  return text;
}

}  // namespace cuetrack::test
