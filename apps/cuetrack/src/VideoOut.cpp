// The video writer on OpenCV's own Motion JPEG writer (videoio), read back at the end.
#include "VideoOut.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <opencv2/videoio.hpp>
#include <string>

#include "CvImage.hpp"
#include "Overlay.hpp"

namespace cuetrack::app {

struct VideoOut::Impl {
  cv::VideoWriter writer;
  std::string path;
  int width = 0, height = 0;  // of the frames (the video is taller: the text strip)
  bool depth = false;
  double fps = 30.0;
};

VideoOut::VideoOut() : _impl(std::make_unique<Impl>()) {}
VideoOut::~VideoOut() = default;

bool VideoOut::open(const char* path, double fps, char* err, size_t errLen) {
  const size_t n = std::strlen(path);
  if (n < 5 || std::strcmp(path + n - 4, ".avi") != 0) {
    std::snprintf(err, errLen, "--video %s: expected a .avi file (Motion JPEG)", path);
    return false;
  }
  // Found out now, before the run: the writer itself only says "cannot open" (after
  // trying GStreamer), and opens on the first frame, whose size it needs.
  FILE* f = std::fopen(path, "wb");
  if (!f) {
    std::snprintf(err, errLen, "--video %s: cannot write: %s", path, std::strerror(errno));
    return false;
  }
  std::fclose(f);
  _impl->path = path;
  _impl->fps = fps > 0.0 ? fps : 30.0;
  return true;
}

bool VideoOut::write(const Frame& frame, const ViewTrack& track, char* err, size_t errLen) {
  Impl& v = *_impl;
  const cv::Mat bgr = toBgr(frame.rgb);
  cv::Mat depth;
  if (frame.hasDepth() && frame.depthMm.width == frame.rgb.width &&
      frame.depthMm.height == frame.rgb.height) {
    depth = cv::Mat(frame.depthMm.height, frame.depthMm.width, CV_16UC1,
                    const_cast<uint16_t*>(frame.depthMm.data),
                    static_cast<size_t>(frame.depthMm.stride) * sizeof(uint16_t));
  }
  if (!v.writer.isOpened()) {
    v.width = frame.rgb.width;
    v.height = frame.rgb.height;
    v.depth = !depth.empty();
    const cv::Size size((v.depth ? 2 : 1) * v.width, v.height + kStripPx);
    // OpenCV's own Motion JPEG writer: no GStreamer or FFmpeg needed.
    if (!v.writer.open(v.path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                       v.fps, size)) {
      std::snprintf(err, errLen, "--video %s: cannot write (folder missing or not writable)",
                    v.path.c_str());
      return false;
    }
  }
  if (frame.rgb.width != v.width || frame.rgb.height != v.height) {
    std::snprintf(err, errLen, "--video %s: frame %u is %dx%d, the video is %dx%d", v.path.c_str(),
                  track.frameIndex, frame.rgb.width, frame.rgb.height, v.width, v.height);
    return false;
  }
  // A frame without depth in a video with depth (or the reverse) keeps the video's layout.
  if (v.depth && depth.empty()) depth = cv::Mat(v.height, v.width, CV_16UC1, cv::Scalar(0));
  if (!v.depth) depth = cv::Mat();
  char line1[160];
  std::snprintf(line1, sizeof line1, "frame %u  %s  confidence %.2f", track.frameIndex,
                trackLook(track).word, track.confidence);
  v.writer.write(
      overlay(bgr, depth, track, line1,
              v.depth ? "cuetrack   depth: near blue, far red, none black" : "cuetrack"));
  ++_frames;
  return true;
}

bool VideoOut::close(char* err, size_t errLen) {
  if (!_impl->writer.isOpened()) return true;
  _impl->writer.release();
  // VideoWriter reports no write error (a full disk, a file size limit): read the video
  // back, as cuetrack-synth does, and count the frames in it.
  cv::VideoCapture cap;
  uint32_t n = 0;
  if (cap.open(_impl->path, cv::CAP_OPENCV_MJPEG) && cap.isOpened())
    while (n < _frames && cap.grab()) ++n;
  if (n != _frames) {
    std::snprintf(err, errLen,
                  "--video %s: only %u of %u frames written could be read back (disk full or "
                  "write error)",
                  _impl->path.c_str(), static_cast<unsigned>(n), static_cast<unsigned>(_frames));
    return false;
  }
  return true;
}

}  // namespace cuetrack::app
