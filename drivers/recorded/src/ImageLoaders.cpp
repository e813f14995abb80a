#include "cuetrack/drivers/ImageLoaders.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "CvImages.hpp"

namespace cuetrack {

const char* depthName(int cvDepth) {
  switch (cvDepth) {
    case CV_8U:
      return "8-bit";
    case CV_16U:
      return "16-bit";
    case CV_32F:
      return "32-bit float";
    default:
      return "another sample type";
  }
}

bool copyColour(const cv::Mat& src, cv::Mat& rgbScratch, FrameSlot& out) {
  if (src.cols > kMaxImageWidth || src.rows > kMaxImageHeight) return false;
  if (src.channels() == 1)
    cv::cvtColor(src, rgbScratch, cv::COLOR_GRAY2RGB);
  else if (src.channels() == 4)
    cv::cvtColor(src, rgbScratch, cv::COLOR_BGRA2RGB);
  else
    cv::cvtColor(src, rgbScratch, cv::COLOR_BGR2RGB);
  out.rgb.resize(src.cols, src.rows);
  for (int y = 0; y < src.rows; ++y)
    std::memcpy(static_cast<void*>(out.rgb.data() + y * src.cols), rgbScratch.ptr(y),
                static_cast<size_t>(src.cols) * 3);
  return true;
}

void copyColourFit(const cv::Mat& src, CvImages& scratch, FrameSlot& out) {
  out.scale = FrameScale::fit(src.cols, src.rows);
  if (!out.scale.scaled()) {
    copyColour(src, scratch.rgb, out);  // fits: cannot fail
    return;
  }
  cv::resize(src, scratch.small, cv::Size(out.scale.widthPx, out.scale.heightPx), 0, 0,
             cv::INTER_AREA);
  copyColour(scratch.small, scratch.rgb, out);
}

bool loadDepthPng16(const char* path, FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>& out,
                    char* err, size_t errLen, float mmPerUnit) {
  const cv::Mat m = cv::imread(path, cv::IMREAD_UNCHANGED);  // a colour PNG stays colour
  if (m.empty()) {
    std::snprintf(err, errLen, "%s: cannot decode image", path);
    return false;
  }
  if (m.type() != CV_16UC1) {
    std::snprintf(err, errLen, "%s: depth must be 16-bit single-channel, not %s with %d channels",
                  path, depthName(m.depth()), m.channels());
    return false;
  }
  if (!out.resize(m.cols, m.rows)) {
    std::snprintf(err, errLen, "%s: %dx%d is larger than %dx%d", path, m.cols, m.rows,
                  kMaxImageWidth, kMaxImageHeight);
    return false;
  }
  for (int y = 0; y < m.rows; ++y)
    std::memcpy(out.data() + y * m.cols, m.ptr(y), static_cast<size_t>(m.cols) * 2);
  if (mmPerUnit != 1.f) {
    uint16_t* d = out.data();
    for (int i = 0; i < m.cols * m.rows; ++i) {
      const long mm = std::lround(static_cast<double>(d[i]) * mmPerUnit);
      d[i] = static_cast<uint16_t>(mm > 65535 ? 65535 : mm);
    }
  }
  return true;
}

bool loadColourImage(const char* path, FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight>& out,
                     char* err, size_t errLen) {
  const cv::Mat m = cv::imread(path, kColourRead);
  if (m.empty()) {
    std::snprintf(err, errLen, "%s: cannot decode image", path);
    return false;
  }
  if (m.depth() != CV_8U) {
    std::snprintf(err, errLen, "%s: colour must be 8 bits per channel, not %s", path,
                  depthName(m.depth()));
    return false;
  }
  if (!out.resize(m.cols, m.rows)) {
    std::snprintf(err, errLen, "%s: %dx%d is larger than %dx%d", path, m.cols, m.rows,
                  kMaxImageWidth, kMaxImageHeight);
    return false;
  }
  cv::Mat rgb;
  cv::cvtColor(m, rgb, cv::COLOR_BGR2RGB);
  for (int y = 0; y < m.rows; ++y)
    std::memcpy(static_cast<void*>(out.data() + y * m.cols), rgb.ptr(y),
                static_cast<size_t>(m.cols) * 3);
  return true;
}

}  // namespace cuetrack
