#include "cuetrack/drivers/OtbFolder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cuetrack/drivers/FileBuffer.hpp"

namespace cuetrack {

bool OtbFolderReader::open(const char* dir, const SourceOptions& opt) {
  startOpen(dir, opt);
  // An OTB folder has its images in img/; a plain image folder has them directly inside.
  const std::string images = rec::isDirectory((_dir + "/img").c_str()) ? _dir + "/img" : _dir;
  if (!listImages(images, &_rgbFiles)) return false;
  return finishOpen(_dir + "/groundtruth_rect.txt", GtFormat::Otb);
}

bool OtbFolderWriter::open(const char* dir) {
  _dir = dir;
  _count = 0;
  _error[0] = '\0';
  if (rec::holdsRecording(dir, _error, sizeof _error)) return false;
  if (!rec::makeDirectories((_dir + "/img").c_str(), _error, sizeof _error)) return false;
  return _gt.open((_dir + "/groundtruth_rect.txt").c_str(), GtFormat::Otb, nullptr, _error,
                  sizeof _error);
}

bool OtbFolderWriter::write(const FrameSlot& frame) {
  const int w = frame.rgb.width(), h = frame.rgb.height();
  cv::Mat rgb(h, w, CV_8UC3, const_cast<Rgb8*>(frame.rgb.data())), bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  char path[1024];
  std::snprintf(path, sizeof path, "%s/img/%04d.jpg", _dir.c_str(), _count + 1);
  if (!cv::imwrite(path, bgr, {cv::IMWRITE_JPEG_QUALITY, 95})) {
    std::snprintf(_error, sizeof _error, "%s: cannot write", path);
    return false;
  }
  // OTB has one line per frame: frames without truth get "0,0,0,0".
  _gt.write(frame.hasGroundTruth ? frame.groundTruth : Box{}, w, h);
  ++_count;
  return true;
}

bool OtbFolderWriter::close() {
  if (!_gt.close()) {
    std::snprintf(_error, sizeof _error, "%s/groundtruth_rect.txt: write failed (%s)", _dir.c_str(),
                  std::strerror(errno));
    return false;
  }
  return true;
}

}  // namespace cuetrack
