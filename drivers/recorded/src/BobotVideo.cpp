#include "cuetrack/drivers/BobotVideo.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "CvImages.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/MediaFiles.hpp"

namespace cuetrack {

struct BobotVideoReader::Video {
  cv::VideoCapture cap;
};

namespace {

bool endsWithAvi(const std::string& p) {
  return p.size() > 4 && p.compare(p.size() - 4, 4, ".avi") == 0;
}

// FFmpeg conceals a damaged frame (it decodes what it can, the rest is grey or smeared)
// and says so only through av_log; OpenCV passes on nothing. So the reader counts the
// errors FFmpeg logs while it reads a frame. The hook goes into the libavutil OpenCV
// itself is linked with, found by dlsym: no FFmpeg headers, no -dev package. It replaces
// FFmpeg's printing to stderr (the reader names the frame instead); a build whose OpenCV
// has no FFmpeg has nothing to hook, and damage is then not detected (docs/recordings.md).
std::atomic<int> gFfmpegErrors{0};

void countFfmpegErrors(void*, int level, const char*, va_list) {
  constexpr int kAvLogError = 16;  // AV_LOG_ERROR; lower levels are worse (fatal, panic)
  if (level <= kAvLogError) gFfmpegErrors.fetch_add(1, std::memory_order_relaxed);
}

bool hookFfmpegLog() {
  static const bool hooked = [] {
    using Callback = void (*)(void*, int, const char*, va_list);
    using SetCallback = void (*)(Callback);
    void* sym = dlsym(RTLD_DEFAULT, "av_log_set_callback");
    if (!sym) return false;
    reinterpret_cast<SetCallback>(sym)(countFfmpegErrors);
    return true;
  }();
  return hooked;
}

}  // namespace

// ---- Reader -----------------------------------------------------------------------

BobotVideoReader::BobotVideoReader() : _video(new Video), _img(new CvImages) {}
BobotVideoReader::~BobotVideoReader() = default;

bool BobotVideoReader::open(const char* videoPath, const SourceOptions& opt) {
  restart(opt);
  _path = videoPath;
  _name = rec::fileStem(_path);
  if (!rec::isFile(videoPath)) {
    std::snprintf(_error, sizeof _error, "%s: no such video file", videoPath);
    return false;
  }
  hookFfmpegLog();
  if (!_video->cap.open(_path, cv::CAP_FFMPEG) || !_video->cap.isOpened()) {
    // The extension named a video: the file is what is wrong, not the format.
    if (rec::fileSize(videoPath) == 0)
      std::snprintf(_error, sizeof _error, "%s: empty file (0 bytes): no video to read", videoPath);
    else
      std::snprintf(_error, sizeof _error,
                    "%s: cannot open video: no stream to decode (the file is cut short, damaged "
                    "or holds no video track; ffprobe %s shows what it holds)",
                    videoPath, videoPath);
    return false;
  }
  const double n = _video->cap.get(cv::CAP_PROP_FRAME_COUNT);
  _frameCount = n > 0 ? static_cast<int>(std::lround(n)) : -1;
  const double fps = _video->cap.get(cv::CAP_PROP_FPS);
  _fps = fps > 1.0 && fps < 1000.0 ? fps : 25.0;
  const GtFormat format = rec::videoGroundTruthFormat(_path.c_str(), opt.gtPath);
  return loadGroundTruth(rec::videoGroundTruthPath(_path.c_str()), format, _frameCount,
                         "video frames");
}

uint64_t BobotVideoReader::frameTimeUs(int i) const {
  return static_cast<uint64_t>(std::llround(i * 1e6 / _fps));
}

RecordedReader::FrameRead BobotVideoReader::readFrame(int i, FrameSlot& out) {
  if (!_video->cap.isOpened()) {
    std::snprintf(_error, sizeof _error, "%s: video not open", _path.c_str());
    return FrameRead::Error;
  }
  const int errorsBefore = gFfmpegErrors.load(std::memory_order_relaxed);
  if (!_video->cap.read(_img->bgr) || _img->bgr.empty()) {
    // Fewer frames than the container announced, or than the ground truth has boxes
    // (a truncated file's header often announces none): a damaged file, not a clean end.
    const int expected = std::max(_frameCount, _gt.count());
    if (i >= expected) return FrameRead::End;
    if (_opt.skipBadFrames) {  // the missing frames count as skipped
      _skipped += expected - i;
      _next = expected;
      return FrameRead::End;
    }
    std::snprintf(_error, sizeof _error, "%s: video ends at frame %d of %d", _path.c_str(), i,
                  expected);
    return FrameRead::Error;
  }
  const int decodeErrors = gFfmpegErrors.load(std::memory_order_relaxed) - errorsBefore;
  if (decodeErrors > 0) {
    std::snprintf(_error, sizeof _error, "%s: frame %d is damaged (%d decoder errors)",
                  _path.c_str(), i, decodeErrors);
    return FrameRead::Bad;
  }
  if (_width > 0 && (_img->bgr.cols != _width || _img->bgr.rows != _height)) {
    std::snprintf(_error, sizeof _error, "%s: frame %d is %dx%d, the video is %dx%d", _path.c_str(),
                  i, _img->bgr.cols, _img->bgr.rows, _width, _height);
    return FrameRead::Bad;
  }
  copyColourFit(_img->bgr, *_img, out);  // a frame larger than the slot is scaled down
  out.hasDepth = false;
  return FrameRead::Ok;
}

// ---- Writer -----------------------------------------------------------------------

struct BobotVideoWriter::Video {
  cv::VideoWriter writer;
  cv::Mat bgr;
};

BobotVideoWriter::BobotVideoWriter() : _video(new Video) {}
BobotVideoWriter::~BobotVideoWriter() = default;

bool BobotVideoWriter::open(const char* aviPath, double fps) {
  _path = aviPath;
  _fps = fps;
  _count = 0;
  _width = _height = 0;
  _error[0] = '\0';
  if (_video->writer.isOpened()) _video->writer.release();
  if (!endsWithAvi(_path)) {
    std::snprintf(_error, sizeof _error, "%s: the video name must end in .avi", aviPath);
    return false;
  }
  if (!(fps >= 1.0 && fps <= 1000.0)) {
    std::snprintf(_error, sizeof _error, "%s: frame rate %g outside 1..1000", aviPath, fps);
    return false;
  }
  const std::string gtPath = _path.substr(0, _path.size() - 4) + ".gt.txt";
  const std::string header = "./" + rec::fileStem(_path) + ".avi";
  return _gt.open(gtPath.c_str(), GtFormat::Bobot, header.c_str(), _error, sizeof _error);
}

bool BobotVideoWriter::write(const FrameSlot& frame) {
  const int w = frame.rgb.width(), h = frame.rgb.height();
  if (!_video->writer.isOpened()) {
    if (w <= 0 || h <= 0 ||
        !_video->writer.open(_path, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                             _fps, cv::Size(w, h))) {
      std::snprintf(_error, sizeof _error, "%s: cannot create video (MJPG, %dx%d)", _path.c_str(),
                    w, h);
      return false;
    }
    _width = w;
    _height = h;
  }
  // OpenCV drops a frame of another size without a word: refuse it here.
  if (w != _width || h != _height) {
    std::snprintf(_error, sizeof _error, "%s: frame %d is %dx%d, the video is %dx%d", _path.c_str(),
                  _count, w, h, _width, _height);
    return false;
  }
  cv::Mat rgb(h, w, CV_8UC3, const_cast<Rgb8*>(frame.rgb.data()));
  cv::cvtColor(rgb, _video->bgr, cv::COLOR_RGB2BGR);
  _video->writer.write(_video->bgr);
  // BoBoT has a line per frame from 0; frames without truth are "not visible".
  _gt.write(frame.hasGroundTruth ? frame.groundTruth : Box{}, w, h);
  ++_count;
  return true;
}

bool BobotVideoWriter::close() {
  const bool wasOpen = _video->writer.isOpened();
  _video->writer.release();
  const bool gtOk = _gt.close();
  const int gtErrno = errno;
  if (wasOpen) {
    // cv::VideoWriter reports no write error (a full disk, a file size limit): read the
    // video back and count the frames that decode. The video first: it is the bigger loss.
    cv::VideoCapture cap;
    int n = 0;
    if (cap.open(_path, cv::CAP_FFMPEG) && cap.isOpened())
      while (n < _count && cap.grab()) ++n;
    if (n != _count) {
      std::snprintf(
          _error, sizeof _error,
          "%s: only %d of %d frames written could be read back (disk full or write error)",
          _path.c_str(), n, _count);
      return false;
    }
  }
  if (!gtOk) {
    std::snprintf(_error, sizeof _error, "%s.gt.txt: write failed (%s)",
                  _path.substr(0, _path.size() - 4).c_str(), std::strerror(gtErrno));
    return false;
  }
  return true;
}

}  // namespace cuetrack
