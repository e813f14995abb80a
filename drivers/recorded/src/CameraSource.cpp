#include "cuetrack/drivers/CameraSource.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <opencv2/videoio.hpp>

#include "CvImages.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedReader.hpp"  // kinectIntrinsicsScaled: no calibration known

namespace cuetrack {

struct CameraSource::Capture {
  cv::VideoCapture cap;
};

namespace {

constexpr int kMaxCameraIndex = 63;
constexpr int kProbedCameras = 10;  // /dev/video0..9 for the default source

uint64_t steadyNowUs() {
  return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                   std::chrono::steady_clock::now().time_since_epoch())
                                   .count());
}

bool isCharDevice(const char* path) {
  struct stat st {};
  return ::stat(path, &st) == 0 && S_ISCHR(st.st_mode);
}

}  // namespace

bool cameraDevice(const char* spec, std::string* device, char* err, size_t errLen) {
  if (std::strcmp(spec, "camera") == 0) {
    *device = "/dev/video0";
    return true;
  }
  if (std::strncmp(spec, "camera:", 7) == 0) {
    const char* rest = spec + 7;
    if (rest[0] == '/') {
      *device = rest;
      return true;
    }
    char* end = nullptr;
    const long n = std::strtol(rest, &end, 10);
    if (rest[0] >= '0' && rest[0] <= '9' && *end == '\0' && n <= kMaxCameraIndex) {
      *device = "/dev/video" + std::to_string(n);
      return true;
    }
  }
  std::snprintf(err, errLen, "%s: expected camera, camera:N (0..%d) or camera:/dev/videoN", spec,
                kMaxCameraIndex);
  return false;
}

bool findCamera(std::string* device) {
  for (int i = 0; i < kProbedCameras; ++i) {
    const std::string path = "/dev/video" + std::to_string(i);
    if (!isCharDevice(path.c_str())) continue;
    cv::VideoCapture cap;
    if (cap.open(path, cv::CAP_V4L2) && cap.isOpened()) {
      *device = path;
      return true;
    }
  }
  return false;
}

CameraSource::CameraSource() : _cap(new Capture), _img(new CvImages) {}
CameraSource::~CameraSource() = default;

bool CameraSource::open(const char* spec) {
  _error[0] = '\0';
  _index = _width = _height = 0;
  _live = true;
  if (!cameraDevice(spec, &_device, _error, sizeof _error)) return false;
  _name = rec::fileStem(_device + ".x");  // "video0"
  if (!rec::exists(_device.c_str())) {
    std::snprintf(_error, sizeof _error,
                  "camera %s: no such device (no V4L2 camera plugged in; --source synth or a "
                  "video runs without one)",
                  _device.c_str());
    return false;
  }
  if (!isCharDevice(_device.c_str()) || !_cap->cap.open(_device, cv::CAP_V4L2) ||
      !_cap->cap.isOpened()) {
    std::snprintf(_error, sizeof _error,
                  "camera %s: cannot open as a V4L2 capture device (busy in another program, no "
                  "permission, or not a camera)",
                  _device.c_str());
    return false;
  }
  const double fps = _cap->cap.get(cv::CAP_PROP_FPS);
  _fps = fps > 0.5 && fps < 1000.0 ? fps : 0.0;
  return true;
}

bool CameraSource::openVideoFile(const char* path) {
  _error[0] = '\0';
  _index = _width = _height = 0;
  _live = false;
  _device = path;
  _name = rec::fileStem(_device);
  if (!rec::isFile(path) || !_cap->cap.open(_device, cv::CAP_FFMPEG) || !_cap->cap.isOpened()) {
    std::snprintf(_error, sizeof _error, "%s: cannot open video", path);
    return false;
  }
  const double fps = _cap->cap.get(cv::CAP_PROP_FPS);
  _fps = fps > 0.5 && fps < 1000.0 ? fps : 25.0;
  return true;
}

ReadStatus CameraSource::next(FrameSlot& out) {
  if (!_cap->cap.isOpened()) {
    std::snprintf(_error, sizeof _error, "camera %s: not open", _device.c_str());
    return ReadStatus::Error;
  }
  if (!_cap->cap.read(_img->bgr) || _img->bgr.empty()) {
    if (!_live) return ReadStatus::End;
    std::snprintf(_error, sizeof _error, "camera %s: no frame after %d (unplugged?)",
                  _device.c_str(), _index);
    return ReadStatus::Error;
  }
  if (_img->bgr.depth() != CV_8U) {
    std::snprintf(_error, sizeof _error, "camera %s: frame %d is not 8 bits per channel",
                  _device.c_str(), _index);
    return ReadStatus::Error;
  }
  if (_width == 0) {
    _width = _img->bgr.cols;
    _height = _img->bgr.rows;
  } else if (_img->bgr.cols != _width || _img->bgr.rows != _height) {
    std::snprintf(_error, sizeof _error, "camera %s: frame %d is %dx%d, the first was %dx%d",
                  _device.c_str(), _index, _img->bgr.cols, _img->bgr.rows, _width, _height);
    return ReadStatus::Error;
  }
  copyColourFit(_img->bgr, *_img, out);
  out.hasDepth = false;
  out.index = _index;
  out.timeUs = _live ? steadyNowUs() : static_cast<uint64_t>(std::llround(_index * 1e6 / _fps));
  out.intrinsics = kinectIntrinsicsScaled(out.rgb.width(), out.rgb.height());
  out.hasGroundTruth = false;
  out.groundTruth = Box{};
  out.hasTruthMm = false;
  ++_index;
  return ReadStatus::Ok;
}

}  // namespace cuetrack
