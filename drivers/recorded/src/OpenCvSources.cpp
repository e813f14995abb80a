#include "cuetrack/drivers/OpenCvSources.hpp"

#include <dirent.h>
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"
#include "cuetrack/drivers/StillPlacement.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

struct CvImages {
  cv::Mat bgr, depth, rgb;
};

struct BobotVideoReader::Video {
  cv::VideoCapture cap;
};

namespace {

std::string stem(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  const size_t slash = p.find_last_of('/');
  std::string base = slash == std::string::npos ? p : p.substr(slash + 1);
  const size_t dot = base.find_last_of('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  return base;
}

bool hasImageExtension(const char* name) {
  const char* dot = std::strrchr(name, '.');
  if (!dot) return false;
  char ext[8] = "";
  for (size_t i = 0; i + 1 < sizeof ext && dot[1 + i]; ++i)
    ext[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(dot[1 + i])));
  return !std::strcmp(ext, "png") || !std::strcmp(ext, "jpg") || !std::strcmp(ext, "jpeg") ||
         !std::strcmp(ext, "ppm") || !std::strcmp(ext, "pgm") || !std::strcmp(ext, "bmp");
}

// Image files of a folder, sorted by name (zero-padded numbers sort right).
bool listImages(const std::string& dir, std::vector<std::string>* out, char* err, size_t errLen) {
  DIR* d = opendir(dir.c_str());
  if (!d) {
    std::snprintf(err, errLen, "%s: cannot open folder", dir.c_str());
    return false;
  }
  std::vector<std::string> names;
  while (dirent* e = readdir(d))
    if (e->d_name[0] != '.' && hasImageExtension(e->d_name)) names.emplace_back(e->d_name);
  closedir(d);
  std::sort(names.begin(), names.end());
  out->clear();
  for (auto& n : names) out->push_back(dir + "/" + n);
  return true;
}

// BGR (or grey) Mat -> RGB slot; false when too large.
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

CameraIntrinsics kinectScaled(int w, int h) {
  const float sx = static_cast<float>(w) / 640.f, sy = static_cast<float>(h) / 480.f;
  return {kKinectV1Intrinsics.fx * sx, kKinectV1Intrinsics.fy * sy, kKinectV1Intrinsics.cx * sx,
          kKinectV1Intrinsics.cy * sy};
}

bool isJpegName(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == "jpg" || ext == "jpeg";
}

// libjpeg decodes a truncated JPEG without an error (the missing rows come out grey, a
// warning goes to stderr): a JPEG must end with its end-of-image marker FF D9 (within
// the last 64 bytes: some writers pad after it). Every JPEG of the shared data does.
bool jpegHasEnd(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  uint8_t tail[64];
  ssize_t n = -1;
  if (::fstat(fd, &st) == 0 && st.st_size >= 4) {
    const off_t from = st.st_size > 64 ? st.st_size - 64 : 0;
    n = ::pread(fd, tail, static_cast<size_t>(st.st_size - from), from);
  }
  ::close(fd);
  for (ssize_t i = 0; i + 1 < n; ++i)
    if (tail[i] == 0xff && tail[i + 1] == 0xd9) return true;
  return false;
}

// Colour as BGR, but a 16-bit image stays 16-bit so that it can be refused rather than
// scaled down without a word (8-bit images read exactly as with IMREAD_COLOR alone).
constexpr int kColourRead = cv::IMREAD_COLOR | cv::IMREAD_ANYDEPTH;

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

bool endsWithAvi(const std::string& p) {
  return p.size() > 4 && p.compare(p.size() - 4, 4, ".avi") == 0;
}

bool gtCountFits(int gt, int frames) {
  return gt == frames || gt == frames - 1;
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

// ---- BoBoT video --------------------------------------------------------------

BobotVideoReader::BobotVideoReader() : _video(new Video), _img(new CvImages) {}
BobotVideoReader::~BobotVideoReader() = default;

bool BobotVideoReader::open(const char* aviPath, const SourceOptions& opt) {
  _path = aviPath;
  _name = stem(_path);
  _opt = opt;
  _next = _skipped = 0;
  _gt = GroundTruth{};
  _error[0] = '\0';
  if (!rec::isFile(aviPath)) {
    std::snprintf(_error, sizeof _error, "%s: no such video file", aviPath);
    return false;
  }
  _width = _height = 0;
  hookFfmpegLog();
  if (!_video->cap.open(_path, cv::CAP_FFMPEG) || !_video->cap.isOpened()) {
    std::snprintf(_error, sizeof _error, "%s: cannot open video (not a format OpenCV decodes)",
                  aviPath);
    return false;
  }
  const double n = _video->cap.get(cv::CAP_PROP_FRAME_COUNT);
  _frameCount = n > 0 ? static_cast<int>(std::lround(n)) : -1;
  const double fps = _video->cap.get(cv::CAP_PROP_FPS);
  _fps = fps > 1.0 && fps < 1000.0 ? fps : 25.0;

  std::string gtPath;
  if (opt.gtPath) {
    gtPath = opt.gtPath;
  } else {
    const size_t dot = _path.find_last_of('.');
    gtPath = (dot == std::string::npos ? _path : _path.substr(0, dot)) + ".gt.txt";
  }
  if (opt.gtPath || rec::exists(gtPath.c_str())) {
    if (!_gt.load(gtPath.c_str(), GtFormat::Bobot, _error, sizeof _error)) return false;
    if (_frameCount > 0 && !gtCountFits(_gt.count(), _frameCount)) {
      std::snprintf(_error, sizeof _error, "%s: %d ground-truth boxes for %d video frames",
                    gtPath.c_str(), _gt.count(), _frameCount);
      return false;
    }
  }
  return true;
}

ReadStatus BobotVideoReader::next(FrameSlot& out) {
  for (;;) {
    if (_opt.maxFrames >= 0 && _next - _skipped >= _opt.maxFrames) return ReadStatus::End;
    if (!_video->cap.isOpened()) {
      std::snprintf(_error, sizeof _error, "%s: video not open", _path.c_str());
      return ReadStatus::Error;
    }
    const int errorsBefore = gFfmpegErrors.load(std::memory_order_relaxed);
    if (!_video->cap.read(_img->bgr) || _img->bgr.empty()) {
      // Fewer frames than the container announced, or than the ground truth has boxes
      // (a truncated file's header often announces none): a damaged file, not a clean end.
      const int expected = std::max(_frameCount, _gt.count());
      if (_next < expected) {
        if (_opt.skipBadFrames) {
          _skipped += expected - _next;
          _next = expected;
          return ReadStatus::End;
        }
        std::snprintf(_error, sizeof _error, "%s: video ends at frame %d of %d", _path.c_str(),
                      _next, expected);
        return ReadStatus::Error;
      }
      return ReadStatus::End;
    }
    const int i = _next++;
    const int decodeErrors = gFfmpegErrors.load(std::memory_order_relaxed) - errorsBefore;
    bool ok = true;
    if (decodeErrors > 0) {
      std::snprintf(_error, sizeof _error, "%s: frame %d is damaged (%d decoder errors)",
                    _path.c_str(), i, decodeErrors);
      ok = false;
    } else if (_width > 0 && (_img->bgr.cols != _width || _img->bgr.rows != _height)) {
      std::snprintf(_error, sizeof _error, "%s: frame %d is %dx%d, the video is %dx%d",
                    _path.c_str(), i, _img->bgr.cols, _img->bgr.rows, _width, _height);
      ok = false;
    } else if (!copyColour(_img->bgr, _img->rgb, out)) {
      std::snprintf(_error, sizeof _error, "%s: frame %d is %dx%d, larger than %dx%d",
                    _path.c_str(), i, _img->bgr.cols, _img->bgr.rows, kMaxImageWidth,
                    kMaxImageHeight);
      ok = false;
    }
    if (!ok) {
      if (_opt.skipBadFrames) {
        ++_skipped;
        continue;
      }
      return ReadStatus::Error;
    }
    if (_width == 0) {
      _width = out.rgb.width();
      _height = out.rgb.height();
    }
    out.hasDepth = false;
    out.index = i;
    out.timeUs = static_cast<uint64_t>(std::llround(i * 1e6 / _fps));
    out.intrinsics = kinectScaled(out.rgb.width(), out.rgb.height());
    out.hasGroundTruth = _gt.boxAt(i, out.rgb.width(), out.rgb.height(), &out.groundTruth);
    if (!out.hasGroundTruth) out.groundTruth = Box{};
    return ReadStatus::Ok;
  }
}

// ---- Image folders --------------------------------------------------------------

ImageFolderReader::ImageFolderReader() : _img(new CvImages) {}
ImageFolderReader::~ImageFolderReader() = default;

bool ImageFolderReader::finishOpen(const char* gtPath, GtFormat format, bool gtRequired) {
  if (_rgbFiles.empty()) {
    std::snprintf(_error, sizeof _error, "%s: no images", _dir.c_str());
    return false;
  }
  const std::string gt = _opt.gtPath ? std::string(_opt.gtPath) : std::string(gtPath);
  if (_opt.gtPath || gtRequired || rec::exists(gt.c_str())) {
    if (!_gt.load(gt.c_str(), format, _error, sizeof _error)) return false;
    if (!gtCountFits(_gt.count(), frameCount())) {
      std::snprintf(_error, sizeof _error, "%s: %d ground-truth boxes for %d frames", gt.c_str(),
                    _gt.count(), frameCount());
      return false;
    }
  }
  return true;
}

bool RgbdFolderReader::open(const char* dir, const SourceOptions& opt) {
  _dir = dir;
  while (_dir.size() > 1 && _dir.back() == '/') _dir.pop_back();
  _name = stem(_dir + ".x");
  _opt = opt;
  _next = _emitted = _skipped = 0;
  _width = _height = 0;
  _error[0] = '\0';
  if (!listImages(_dir + "/rgb", &_rgbFiles, _error, sizeof _error)) return false;
  if (!listImages(_dir + "/depth", &_depthFiles, _error, sizeof _error)) return false;
  if (_depthFiles.size() != _rgbFiles.size()) {
    std::snprintf(_error, sizeof _error, "%s/depth: %zu depth images for %zu colour images",
                  _dir.c_str(), _depthFiles.size(), _rgbFiles.size());
    return false;
  }
  const std::string kPath = _dir + "/intrinsics.txt";
  _haveIntrinsics = false;
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
  return finishOpen((_dir + "/groundtruth.txt").c_str(), GtFormat::Bobot, false);
}

bool OtbFolderReader::open(const char* dir, const SourceOptions& opt) {
  _dir = dir;
  while (_dir.size() > 1 && _dir.back() == '/') _dir.pop_back();
  _name = stem(_dir + ".x");
  _opt = opt;
  _next = _emitted = _skipped = 0;
  _width = _height = 0;
  _error[0] = '\0';
  _depthFiles.clear();
  _haveIntrinsics = false;
  if (!listImages(_dir + "/img", &_rgbFiles, _error, sizeof _error)) return false;
  return finishOpen((_dir + "/groundtruth_rect.txt").c_str(), GtFormat::Otb, false);
}

ReadStatus ImageFolderReader::next(FrameSlot& out) {
  for (;;) {
    if (_next >= frameCount()) return ReadStatus::End;
    if (_opt.maxFrames >= 0 && _emitted >= _opt.maxFrames) return ReadStatus::End;
    const int i = _next++;
    const std::string& rgbPath = _rgbFiles[static_cast<size_t>(i)];
    bool ok = true;
    // imread would block on a FIFO and read a device: regular files only.
    if (!rec::isFile(rgbPath.c_str())) {
      std::snprintf(_error, sizeof _error, "%s: not a regular file", rgbPath.c_str());
      ok = false;
    } else if (isJpegName(rgbPath) && !jpegHasEnd(rgbPath)) {
      std::snprintf(_error, sizeof _error, "%s: truncated JPEG (no end-of-image marker)",
                    rgbPath.c_str());
      ok = false;
    } else if ((_img->bgr = cv::imread(rgbPath, kColourRead)).empty()) {
      std::snprintf(_error, sizeof _error,
                    "%s: cannot decode image (missing, truncated or corrupt)", rgbPath.c_str());
      ok = false;
    } else if (_img->bgr.depth() != CV_8U) {
      std::snprintf(_error, sizeof _error, "%s: colour must be 8 bits per channel, not %s",
                    rgbPath.c_str(), depthName(_img->bgr.depth()));
      ok = false;
    } else if (_width > 0 && (_img->bgr.cols != _width || _img->bgr.rows != _height)) {
      std::snprintf(_error, sizeof _error, "%s: %dx%d, the sequence is %dx%d", rgbPath.c_str(),
                    _img->bgr.cols, _img->bgr.rows, _width, _height);
      ok = false;
    } else if (!copyColour(_img->bgr, _img->rgb, out)) {
      std::snprintf(_error, sizeof _error, "%s: %dx%d is larger than %dx%d", rgbPath.c_str(),
                    _img->bgr.cols, _img->bgr.rows, kMaxImageWidth, kMaxImageHeight);
      ok = false;
    } else if (_haveIntrinsics && (_intrinsics.cx > static_cast<float>(out.rgb.width()) ||
                                   _intrinsics.cy > static_cast<float>(out.rgb.height()))) {
      // parseIntrinsics checked fx, fy and cx, cy >= 0; the image size is known only now.
      std::snprintf(_error, sizeof _error,
                    "%s/intrinsics.txt: principal point %g,%g outside the %dx%d image",
                    _dir.c_str(), static_cast<double>(_intrinsics.cx),
                    static_cast<double>(_intrinsics.cy), out.rgb.width(), out.rgb.height());
      ok = false;
    }
    out.hasDepth = false;
    if (ok && !_depthFiles.empty()) {
      const std::string& dPath = _depthFiles[static_cast<size_t>(i)];
      if (!rec::isFile(dPath.c_str())) {
        std::snprintf(_error, sizeof _error, "%s: not a regular file", dPath.c_str());
        ok = false;
      } else if ((_img->depth = cv::imread(dPath, cv::IMREAD_UNCHANGED)).empty()) {
        std::snprintf(_error, sizeof _error,
                      "%s: cannot decode depth image (missing, truncated or corrupt)",
                      dPath.c_str());
        ok = false;
      } else if (_img->depth.type() != CV_16UC1) {
        std::snprintf(_error, sizeof _error,
                      "%s: depth must be 16-bit single-channel, not %s with %d channels",
                      dPath.c_str(), depthName(_img->depth.depth()), _img->depth.channels());
        ok = false;
      } else if (_img->depth.cols != out.rgb.width() || _img->depth.rows != out.rgb.height()) {
        std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d",
                      dPath.c_str(), _img->depth.cols, _img->depth.rows, out.rgb.width(),
                      out.rgb.height());
        ok = false;
      } else {
        out.depthMm.resize(_img->depth.cols, _img->depth.rows);
        for (int y = 0; y < _img->depth.rows; ++y)
          std::memcpy(out.depthMm.data() + y * _img->depth.cols, _img->depth.ptr(y),
                      static_cast<size_t>(_img->depth.cols) * 2);
        out.hasDepth = true;
      }
    }
    if (!ok) {
      if (_opt.skipBadFrames) {
        ++_skipped;
        continue;
      }
      return ReadStatus::Error;
    }
    if (_width == 0) {
      _width = out.rgb.width();
      _height = out.rgb.height();
    }
    out.index = i;
    out.timeUs = static_cast<uint64_t>(std::llround(i * 1e6 / _fps));
    out.intrinsics =
        _haveIntrinsics ? _intrinsics : kinectScaled(out.rgb.width(), out.rgb.height());
    out.hasGroundTruth = _gt.boxAt(i, out.rgb.width(), out.rgb.height(), &out.groundTruth);
    if (!out.hasGroundTruth) out.groundTruth = Box{};
    ++_emitted;
    return ReadStatus::Ok;
  }
}

// ---- RGB-D folder writer --------------------------------------------------------

bool RgbdFolderWriter::open(const char* dir, const char* sequenceName) {
  char* err = _error;
  const size_t errLen = sizeof _error;
  _error[0] = '\0';
  _dir = dir;
  _name = sequenceName ? sequenceName : stem(_dir + ".x");
  _count = 0;
  _gtOpen = false;
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
    const CameraIntrinsics k = frame.intrinsics.valid() ? frame.intrinsics : kinectScaled(w, h);
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
  if (frame.hasGroundTruth) {
    if (!_gtOpen) {
      if (_count > 0) {
        std::snprintf(err, errLen, "%s: ground truth starts at frame %d, not 0", _dir.c_str(),
                      _count);
        return false;
      }
      if (!_gt.open((_dir + "/groundtruth.txt").c_str(), GtFormat::Bobot, _name.c_str(), err,
                    errLen))
        return false;
      _gtOpen = true;
    }
    _gt.write(frame.groundTruth, w, h);
  }
  ++_count;
  return true;
}

bool RgbdFolderWriter::close() {
  char* err = _error;
  const size_t errLen = sizeof _error;
  if (_gtOpen && !_gt.close()) {
    std::snprintf(err, errLen, "%s/groundtruth.txt: write failed (%s)", _dir.c_str(),
                  std::strerror(errno));
    return false;
  }
  _gtOpen = false;
  return true;
}

// ---- OTB folder writer ----------------------------------------------------------

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

// ---- BoBoT video writer -----------------------------------------------------------

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
  const std::string header = "./" + stem(_path) + ".avi";
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

// ---- Stills ---------------------------------------------------------------------

bool loadDepthPng16(const char* path, FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>& out,
                    char* err, size_t errLen) {
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

// ---- A real RGB-D still, panned ---------------------------------------------------

namespace cuetrack {

namespace {

bool parseFloat(const std::string& s, float* out) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v)) return false;
  *out = static_cast<float>(v);
  return true;
}

// The comma-separated fields of s.
std::vector<std::string> splitFields(const std::string& s) {
  std::vector<std::string> f;
  for (size_t start = 0;;) {
    const size_t comma = s.find(',', start);
    f.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return f;
    start = comma + 1;
  }
}

// f[first..] as numbers into out[0..], named by names[] in the error of the first that is
// not one.
bool parseNumbers(const std::vector<std::string>& f, size_t first, float* out,
                  const char* const* names, const char* spec, char* err, size_t errLen) {
  for (size_t i = first; i < f.size(); ++i) {
    if (!parseFloat(f[i], &out[i - first])) {
      std::snprintf(err, errLen, "%s: %s '%s' is not a number", spec, names[i - first],
                    f[i].c_str());
      return false;
    }
  }
  return true;
}

// A still's label for sequence names: the folder above color/ or rgb/ (or its own
// folder) and the image's stem, e.g. nyu-joinmap-5.
std::string stillLabel(const std::string& rgbPath) {
  const auto lastPart = [](const std::string& p) {
    const size_t k = p.find_last_of('/');
    return k == std::string::npos ? p : p.substr(k + 1);
  };
  const size_t slash = rgbPath.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : rgbPath.substr(0, slash);
  std::string folder = lastPart(dir);
  if ((folder == "color" || folder == "rgb") && dir.find('/') != std::string::npos)
    folder = lastPart(dir.substr(0, dir.find_last_of('/')));
  return (folder.empty() ? std::string() : folder + "-") + stem(rgbPath);
}

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
  std::string body = spec;
  if (body.rfind("pan:", 0) == 0) body = body.substr(4);
  // Optional ":frames" after the last field.
  _frames = 150;
  const size_t lastComma = body.find_last_of(',');
  const size_t colon = body.find(':', lastComma == std::string::npos ? 0 : lastComma);
  if (colon != std::string::npos) {
    const std::string n = body.substr(colon + 1);
    if (!rec::parseFrameCount(n.c_str(), &_frames)) {
      std::snprintf(_error, sizeof _error, "%s: frame count '%s' is not a number in 1..%ld", spec,
                    n.c_str(), rec::kMaxSpecFrames);
      return false;
    }
    body = body.substr(0, colon);
  }
  const std::vector<std::string> f = splitFields(body);
  if (f.size() != 10 && f.size() != 11) {
    std::snprintf(_error, sizeof _error,
                  "%s: expected pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames] "
                  "(%zu fields)",
                  spec, f.size());
    return false;
  }
  float v[9] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 1.f};
  static const char* const kField[9] = {"x", "y", "w", "h", "fx", "fy", "cx", "cy", "mmPerUnit"};
  if (!parseNumbers(f, 2, v, kField, spec, _error, sizeof _error)) return false;
  if (!(v[2] > 0.f) || !(v[3] > 0.f) || !(v[4] > 0.f) || !(v[5] > 0.f) || !(v[8] > 0.f)) {
    std::snprintf(_error, sizeof _error, "%s: w, h, fx, fy and mmPerUnit must be positive", spec);
    return false;
  }
  if (opt.maxFrames >= 0 && opt.maxFrames < _frames) _frames = opt.maxFrames;
  const std::string& rgbPath = f[0];
  const std::string& depthPath = f[1];
  // Name: the still's label and the box's corner, e.g. pan-nyu-joinmap-5-302-102: two
  // targets of one still get two names.
  char corner[48];
  std::snprintf(corner, sizeof corner, "-%ld-%ld", std::lround(v[0]), std::lround(v[1]));
  _name = "pan-" + stillLabel(rgbPath) + corner;

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
  if (v[8] == 1.f)
    _img->depth = depth;
  else
    depth.convertTo(_img->depth, CV_16U, static_cast<double>(v[8]));  // rounds, saturates
  _box = Box{v[0], v[1], v[2], v[3]};
  const Box inside =
      intersectBox(_box, Box{0.f, 0.f, static_cast<float>(bgr.cols), static_cast<float>(bgr.rows)});
  if (inside.empty()) {
    std::snprintf(_error, sizeof _error, "%s: box %g,%g %gx%g lies outside the %dx%d still", spec,
                  static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2]),
                  static_cast<double>(v[3]), bgr.cols, bgr.rows);
    return false;
  }
  _marginX = bgr.cols / 16;
  _marginY = bgr.rows / 16;
  _cropW = bgr.cols - 2 * _marginX;
  _cropH = bgr.rows - 2 * _marginY;
  _k = CameraIntrinsics{v[4], v[5], v[6] - static_cast<float>(_marginX),
                        v[7] - static_cast<float>(_marginY)};
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

// ---- A synthetic scene in a real RGB-D still ----------------------------------------

namespace cuetrack {

struct StillSceneReader::Still {
  FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight> rgb;
  FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight> depthMm;
};

StillSceneReader::StillSceneReader() : _still(new Still) {}
StillSceneReader::~StillSceneReader() = default;

int StillSceneReader::frameCount() const {
  return _scene ? _scene->frameCount() : -1;
}

double StillSceneReader::nominalFps() const {
  return _scene ? _scene->nominalFps() : 0.0;
}

bool StillSceneReader::open(const char* spec, const SourceOptions& opt) {
  _error[0] = '\0';
  _scene.reset();
  static const char kSyntax[] = "still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]";
  std::string body = spec;
  if (body.rfind("still:", 0) == 0) body = body.substr(6);
  // From the right: "@u,v,gapMm[:frames]", then ":SCENE"; the paths keep any '@' or ':'.
  const size_t at = body.find_last_of('@');
  const size_t sceneColon = at == std::string::npos ? at : body.find_last_of(':', at);
  if (at == std::string::npos || sceneColon == std::string::npos) {
    std::snprintf(_error, sizeof _error, "%s: expected %s (no :SCENE@u,v,gapMm)", spec, kSyntax);
    return false;
  }
  const std::string scene = body.substr(sceneColon + 1, at - sceneColon - 1);
  std::string place = body.substr(at + 1);
  int frames = -1;
  const size_t framesColon = place.find(':');
  if (framesColon != std::string::npos) {
    const std::string n = place.substr(framesColon + 1);
    if (!rec::parseFrameCount(n.c_str(), &frames)) {
      std::snprintf(_error, sizeof _error, "%s: frame count '%s' is not a number in 1..%ld", spec,
                    n.c_str(), rec::kMaxSpecFrames);
      return false;
    }
    place = place.substr(0, framesColon);
  }
  const std::vector<std::string> f = splitFields(body.substr(0, sceneColon));
  const std::vector<std::string> p = splitFields(place);
  if ((f.size() != 6 && f.size() != 7) || p.size() != 3) {
    std::snprintf(_error, sizeof _error, "%s: expected %s (%zu still fields, %zu placement fields)",
                  spec, kSyntax, f.size(), p.size());
    return false;
  }
  float k[5] = {0.f, 0.f, 0.f, 0.f, 1.f};
  static const char* const kField[5] = {"fx", "fy", "cx", "cy", "mmPerUnit"};
  float uvGap[3] = {0.f, 0.f, 0.f};
  static const char* const kPlaceField[3] = {"u", "v", "gapMm"};
  if (!parseNumbers(f, 2, k, kField, spec, _error, sizeof _error) ||
      !parseNumbers(p, 0, uvGap, kPlaceField, spec, _error, sizeof _error))
    return false;
  if (!(k[0] > 0.f) || !(k[1] > 0.f) || !(k[4] > 0.f)) {
    std::snprintf(_error, sizeof _error, "%s: fx, fy and mmPerUnit must be positive", spec);
    return false;
  }
  if (!(uvGap[2] >= 0.f)) {
    std::snprintf(_error, sizeof _error, "%s: gapMm must be >= 0 (the target in front)", spec);
    return false;
  }
  SceneSpec s;
  if (!makeScene(scene.c_str(), &s)) {
    std::string names;
    for (int i = 0; i < sceneCount(); ++i) names += std::string(i ? ", " : "") + sceneName(i);
    std::snprintf(_error, sizeof _error, "%s: unknown scene '%s' (scenes: %s)", spec, scene.c_str(),
                  names.c_str());
    return false;
  }
  if (!loadColourImage(f[0].c_str(), _still->rgb, _error, sizeof _error) ||
      !loadDepthPng16(f[1].c_str(), _still->depthMm, _error, sizeof _error))
    return false;
  const int w = _still->rgb.width(), h = _still->rgb.height();
  if (w < 32 || h < 32) {
    std::snprintf(_error, sizeof _error, "%s: %dx%d is smaller than 32x32", f[0].c_str(), w, h);
    return false;
  }
  if (_still->depthMm.width() != w || _still->depthMm.height() != h) {
    std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d",
                  f[1].c_str(), _still->depthMm.width(), _still->depthMm.height(), w, h);
    return false;
  }
  if (k[4] != 1.f) {
    uint16_t* d = _still->depthMm.data();
    for (int i = 0; i < w * h; ++i) {
      const long mm = std::lround(static_cast<double>(d[i]) * k[4]);
      d[i] = static_cast<uint16_t>(mm > 65535 ? 65535 : mm);
    }
  }
  s.width = w;
  s.height = h;
  if (frames > 0) s.frameCount = frames;
  if (opt.maxFrames >= 0 && opt.maxFrames < s.frameCount) s.frameCount = opt.maxFrames;
  const CameraIntrinsics intrinsics{k[0], k[1], k[2], k[3]};
  char why[256];
  if (!placeInStill(&s, _still->depthMm.data(), w, h, intrinsics, uvGap[0], uvGap[1], uvGap[2], why,
                    sizeof why)) {
    std::snprintf(_error, sizeof _error, "%s: %s", spec, why);
    return false;
  }
  // Named by the still's label, the scene and the pixel, e.g.
  // still-tum-fr1-1-flat-turn-250-170.
  char pixel[48];
  std::snprintf(pixel, sizeof pixel, "-%ld-%ld", std::lround(uvGap[0]), std::lround(uvGap[1]));
  _name = "still-" + stillLabel(f[0]) + "-" + scene + pixel;
  std::snprintf(s.name, sizeof s.name, "%s", _name.c_str());
  _scene = std::make_unique<SyntheticSource>(s, opt.seed);
  if (_scene->error()[0]) {
    std::snprintf(_error, sizeof _error, "%s: %s", spec, _scene->error());
    _scene.reset();
    return false;
  }
  _scene->setBackdrop(_still->rgb.data(), _still->depthMm.data(), intrinsics);
  return true;
}

ReadStatus StillSceneReader::next(FrameSlot& out) {
  if (!_scene) {
    std::snprintf(_error, sizeof _error, "still: scene not open");
    return ReadStatus::Error;
  }
  const ReadStatus r = _scene->next(out);
  if (r == ReadStatus::Error) std::snprintf(_error, sizeof _error, "%s", _scene->error());
  return r;
}

}  // namespace cuetrack
