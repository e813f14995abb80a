#include "cuetrack/drivers/RgbdFolder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

namespace cuetrack {

bool RgbdFolderReader::open(const char* dir, const SourceOptions& opt) {
  startOpen(dir, opt);
  if (!listImages(_dir + "/rgb", &_rgbFiles)) return false;
  if (!listImages(_dir + "/depth", &_depthFiles)) return false;
  if (_depthFiles.size() != _rgbFiles.size()) {
    std::snprintf(_error, sizeof _error, "%s/depth: %zu depth images for %zu colour images",
                  _dir.c_str(), _depthFiles.size(), _rgbFiles.size());
    return false;
  }
  const std::string kPath = _dir + "/intrinsics.txt";
  if (rec::exists(kPath.c_str())) {
    std::vector<uint8_t> text;
    if (!rec::readFile(kPath.c_str(), text, _error, sizeof _error)) return false;
    char why[160];
    if (!rec::parseIntrinsics(reinterpret_cast<const char*>(text.data()), text.size(), &_intrinsics,
                              why, sizeof why)) {
      std::snprintf(_error, sizeof _error, "%s: %s", kPath.c_str(), why);
      return false;
    }
    _haveIntrinsics = true;
  }
  return finishOpen(_dir + "/groundtruth.txt", GtFormat::Bobot);
}

bool RgbdFolderWriter::open(const char* dir, const char* sequenceName) {
  char* err = _error;
  const size_t errLen = sizeof _error;
  _error[0] = '\0';
  _dir = dir;
  _name = sequenceName ? sequenceName : rec::fileStem(_dir + ".x");
  _count = 0;
  _gt.start(_dir, _name);
  _wroteIntrinsics = false;
  if (rec::holdsRecording(dir, err, errLen)) return false;
  return rec::makeDirectories((_dir + "/rgb").c_str(), err, errLen) &&
         rec::makeDirectories((_dir + "/depth").c_str(), err, errLen);
}

bool RgbdFolderWriter::write(const FrameSlot& frame) {
  char* err = _error;
  const size_t errLen = sizeof _error;
  const int w = frame.rgb.width(), h = frame.rgb.height();
  char path[1024];
  if (!_wroteIntrinsics) {
    const CameraIntrinsics k =
        frame.intrinsics.valid() ? frame.intrinsics : kinectIntrinsicsScaled(w, h);
    char line[128];
    const int n = std::snprintf(line, sizeof line, "%.4f %.4f %.4f %.4f\n",
                                static_cast<double>(k.fx), static_cast<double>(k.fy),
                                static_cast<double>(k.cx), static_cast<double>(k.cy));
    std::snprintf(path, sizeof path, "%s/intrinsics.txt", _dir.c_str());
    if (!rec::writeFile(path, line, static_cast<size_t>(n), err, errLen)) return false;
    _wroteIntrinsics = true;
  }
  cv::Mat rgb(h, w, CV_8UC3, const_cast<Rgb8*>(frame.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::snprintf(path, sizeof path, "%s/rgb/%06d.png", _dir.c_str(), _count);
  if (!cv::imwrite(path, bgr)) {
    std::snprintf(err, errLen, "%s: cannot write", path);
    return false;
  }
  cv::Mat depth = frame.hasDepth
                      ? cv::Mat(h, w, CV_16UC1, const_cast<uint16_t*>(frame.depthMm.data()))
                      : cv::Mat(h, w, CV_16UC1, cv::Scalar(0));
  std::snprintf(path, sizeof path, "%s/depth/%06d.png", _dir.c_str(), _count);
  if (!cv::imwrite(path, depth)) {
    std::snprintf(err, errLen, "%s: cannot write", path);
    return false;
  }
  if (!_gt.write(frame, _count, err, errLen)) return false;
  ++_count;
  return true;
}

bool RgbdFolderWriter::close() {
  return _gt.close(_error, sizeof _error);
}

}  // namespace cuetrack
