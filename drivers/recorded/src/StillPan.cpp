#include "cuetrack/drivers/StillPan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <opencv2/imgproc.hpp>

#include "CvImages.hpp"
#include "cuetrack/drivers/StillSpecs.hpp"

namespace cuetrack {

namespace {

// The part of a inside b (empty when they do not meet).
Box intersectBox(const Box& a, const Box& b) {
  const float x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
  const float x1 = std::min(a.x + a.w, b.x + b.w), y1 = std::min(a.y + a.h, b.y + b.h);
  if (!(x1 > x0) || !(y1 > y0)) return Box{};
  return Box{x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

StillPanReader::StillPanReader() : _img(new CvImages) {}
StillPanReader::~StillPanReader() = default;

bool StillPanReader::open(const char* spec, const SourceOptions& opt) {
  _error[0] = '\0';
  _next = 0;
  _seed = opt.seed;
  rec::PanSpec p;
  if (!rec::parsePanSpec(spec, &p, _error, sizeof _error)) return false;
  _frames = p.frames;
  if (opt.maxFrames >= 0 && opt.maxFrames < _frames) _frames = opt.maxFrames;
  const std::string& rgbPath = p.rgbPath;
  const std::string& depthPath = p.depthPath;
  // Name: the still's label and the box's corner, e.g. pan-nyu-joinmap-5-302-102: two
  // targets of one still get two names.
  char corner[48];
  std::snprintf(corner, sizeof corner, "-%ld-%ld", std::lround(p.box.x), std::lround(p.box.y));
  _name = "pan-" + rec::stillLabel(rgbPath) + corner;

  const cv::Mat bgr = cv::imread(rgbPath, kColourRead);
  if (bgr.empty()) {
    std::snprintf(_error, sizeof _error, "%s: cannot decode image (missing, truncated or corrupt)",
                  rgbPath.c_str());
    return false;
  }
  if (bgr.depth() != CV_8U) {
    std::snprintf(_error, sizeof _error, "%s: colour must be 8 bits per channel, not %s",
                  rgbPath.c_str(), depthName(bgr.depth()));
    return false;
  }
  if (bgr.cols > kMaxImageWidth || bgr.rows > kMaxImageHeight || bgr.cols < 32 || bgr.rows < 32) {
    std::snprintf(_error, sizeof _error, "%s: %dx%d is not within 32x32 .. %dx%d", rgbPath.c_str(),
                  bgr.cols, bgr.rows, kMaxImageWidth, kMaxImageHeight);
    return false;
  }
  const cv::Mat depth = cv::imread(depthPath, cv::IMREAD_UNCHANGED);
  if (depth.empty()) {
    std::snprintf(_error, sizeof _error,
                  "%s: cannot decode depth image (missing, truncated or corrupt)",
                  depthPath.c_str());
    return false;
  }
  if (depth.type() != CV_16UC1) {
    std::snprintf(_error, sizeof _error,
                  "%s: depth must be 16-bit single-channel, not %s with %d channels",
                  depthPath.c_str(), depthName(depth.depth()), depth.channels());
    return false;
  }
  if (depth.cols != bgr.cols || depth.rows != bgr.rows) {
    std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d",
                  depthPath.c_str(), depth.cols, depth.rows, bgr.cols, bgr.rows);
    return false;
  }
  cv::cvtColor(bgr, _img->bgr, cv::COLOR_BGR2RGB);  // kept as RGB
  if (p.mmPerUnit == 1.f)
    _img->depth = depth;
  else
    depth.convertTo(_img->depth, CV_16U, static_cast<double>(p.mmPerUnit));  // rounds, saturates
  _box = p.box;
  const Box inside =
      intersectBox(_box, Box{0.f, 0.f, static_cast<float>(bgr.cols), static_cast<float>(bgr.rows)});
  if (inside.empty()) {
    std::snprintf(_error, sizeof _error, "%s: box %g,%g %gx%g lies outside the %dx%d still", spec,
                  static_cast<double>(_box.x), static_cast<double>(_box.y),
                  static_cast<double>(_box.w), static_cast<double>(_box.h), bgr.cols, bgr.rows);
    return false;
  }
  _marginX = bgr.cols / 16;
  _marginY = bgr.rows / 16;
  _cropW = bgr.cols - 2 * _marginX;
  _cropH = bgr.rows - 2 * _marginY;
  _k = CameraIntrinsics{p.intrinsics.fx, p.intrinsics.fy,
                        p.intrinsics.cx - static_cast<float>(_marginX),
                        p.intrinsics.cy - static_cast<float>(_marginY)};
  return true;
}

ReadStatus StillPanReader::next(FrameSlot& out) {
  if (_img->bgr.empty()) {
    std::snprintf(_error, sizeof _error, "pan: still not open");
    return ReadStatus::Error;
  }
  if (_next >= _frames) return ReadStatus::End;
  const int i = _next++;
  constexpr double kTwoPi = 6.283185307179586;
  const int ox = _marginX + static_cast<int>(std::lround(_marginX * std::sin(kTwoPi * i / 60.0)));
  const int oy = _marginY + static_cast<int>(
                                std::lround(_marginY * (5.0 / 6.0) * std::sin(kTwoPi * i / 90.0)));
  // Colour: the crop plus Gaussian noise, the same for a seed and frame on every run.
  cv::Mat crop;
  _img->bgr(cv::Rect(ox, oy, _cropW, _cropH)).convertTo(crop, CV_16SC3);
  cv::Mat noise(crop.size(), CV_16SC3);
  cv::RNG rng(_seed * 1000003u + static_cast<uint64_t>(i));
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 2.0);
  crop += noise;
  crop.convertTo(_img->rgb, CV_8UC3);  // saturates to 0..255
  out.rgb.resize(_cropW, _cropH);
  for (int y = 0; y < _cropH; ++y)
    std::memcpy(static_cast<void*>(out.rgb.data() + y * _cropW), _img->rgb.ptr(y),
                static_cast<size_t>(_cropW) * 3);
  out.depthMm.resize(_cropW, _cropH);
  for (int y = 0; y < _cropH; ++y)
    std::memcpy(out.depthMm.data() + y * _cropW, _img->depth.ptr<uint16_t>(oy + y) + ox,
                static_cast<size_t>(_cropW) * 2);
  out.hasDepth = true;
  out.index = i;
  out.timeUs = static_cast<uint64_t>(std::llround(i * 1e6 / 30.0));
  out.intrinsics = _k;
  const Box shifted{_box.x - static_cast<float>(ox), _box.y - static_cast<float>(oy), _box.w,
                    _box.h};
  out.hasGroundTruth = true;
  out.groundTruth =
      intersectBox(shifted, Box{0.f, 0.f, static_cast<float>(_cropW), static_cast<float>(_cropH)});
  return ReadStatus::Ok;
}

}  // namespace cuetrack
