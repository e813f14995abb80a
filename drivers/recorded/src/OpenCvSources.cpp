#include "cuetrack/drivers/OpenCvSources.hpp"

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

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

bool endsWithAvi(const std::string& p) {
  return p.size() > 4 && p.compare(p.size() - 4, 4, ".avi") == 0;
}

bool gtCountFits(int gt, int frames) {
  return gt == frames || gt == frames - 1;
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
  _error[0] = '\0';
  if (!rec::isFile(aviPath)) {
    std::snprintf(_error, sizeof _error, "%s: no such video file", aviPath);
    return false;
  }
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
  if (opt.gtPath || rec::isFile(gtPath.c_str())) {
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
    if (!_video->cap.read(_img->bgr) || _img->bgr.empty()) {
      // Fewer frames than the container announced: a damaged file, not a clean end.
      if (_frameCount > 0 && _next < _frameCount && !_opt.skipBadFrames) {
        std::snprintf(_error, sizeof _error, "%s: frame %d of %d cannot be decoded", _path.c_str(),
                      _next, _frameCount);
        return ReadStatus::Error;
      }
      return ReadStatus::End;
    }
    const int i = _next++;
    if (!copyColour(_img->bgr, _img->rgb, out)) {
      std::snprintf(_error, sizeof _error, "%s: frame %d is %dx%d, larger than %dx%d",
                    _path.c_str(), i, _img->bgr.cols, _img->bgr.rows, kMaxImageWidth,
                    kMaxImageHeight);
      if (_opt.skipBadFrames) {
        ++_skipped;
        continue;
      }
      return ReadStatus::Error;
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
  if (_opt.gtPath || gtRequired || rec::isFile(gt.c_str())) {
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
  if (rec::isFile(kPath.c_str())) {
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
    _img->bgr = cv::imread(rgbPath, cv::IMREAD_COLOR);
    if (_img->bgr.empty()) {
      std::snprintf(_error, sizeof _error,
                    "%s: cannot decode image (missing, truncated or corrupt)", rgbPath.c_str());
      ok = false;
    } else if (!copyColour(_img->bgr, _img->rgb, out)) {
      std::snprintf(_error, sizeof _error, "%s: %dx%d is larger than %dx%d", rgbPath.c_str(),
                    _img->bgr.cols, _img->bgr.rows, kMaxImageWidth, kMaxImageHeight);
      ok = false;
    }
    out.hasDepth = false;
    if (ok && !_depthFiles.empty()) {
      const std::string& dPath = _depthFiles[static_cast<size_t>(i)];
      _img->depth = cv::imread(dPath, cv::IMREAD_ANYDEPTH);
      if (_img->depth.empty()) {
        std::snprintf(_error, sizeof _error,
                      "%s: cannot decode depth image (missing, truncated or corrupt)",
                      dPath.c_str());
        ok = false;
      } else if (_img->depth.type() != CV_16UC1) {
        std::snprintf(_error, sizeof _error, "%s: depth must be a 16-bit single-channel PNG",
                      dPath.c_str());
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
    std::snprintf(err, errLen, "%s/groundtruth.txt: write failed", _dir.c_str());
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
    std::snprintf(_error, sizeof _error, "%s/groundtruth_rect.txt: write failed", _dir.c_str());
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
  _error[0] = '\0';
  if (!endsWithAvi(_path)) {
    std::snprintf(_error, sizeof _error, "%s: the video name must end in .avi", aviPath);
    return false;
  }
  const std::string gtPath = _path.substr(0, _path.size() - 4) + ".gt.txt";
  const std::string header = "./" + stem(_path) + ".avi";
  return _gt.open(gtPath.c_str(), GtFormat::Bobot, header.c_str(), _error, sizeof _error);
}

bool BobotVideoWriter::write(const FrameSlot& frame) {
  const int w = frame.rgb.width(), h = frame.rgb.height();
  if (!_video->writer.isOpened()) {
    if (!_video->writer.open(_path, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                             _fps, cv::Size(w, h))) {
      std::snprintf(_error, sizeof _error, "%s: cannot create video (MJPG)", _path.c_str());
      return false;
    }
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
  _video->writer.release();
  if (!_gt.close()) {
    std::snprintf(_error, sizeof _error, "%s: ground truth write failed", _path.c_str());
    return false;
  }
  return true;
}

// ---- Stills ---------------------------------------------------------------------

bool loadDepthPng16(const char* path, FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>& out,
                    char* err, size_t errLen) {
  const cv::Mat m = cv::imread(path, cv::IMREAD_ANYDEPTH);
  if (m.empty()) {
    std::snprintf(err, errLen, "%s: cannot decode image", path);
    return false;
  }
  if (m.type() != CV_16UC1) {
    std::snprintf(err, errLen, "%s: not a 16-bit single-channel image", path);
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
  const cv::Mat m = cv::imread(path, cv::IMREAD_COLOR);
  if (m.empty()) {
    std::snprintf(err, errLen, "%s: cannot decode image", path);
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
