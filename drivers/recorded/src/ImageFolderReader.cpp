#include "cuetrack/drivers/ImageFolderReader.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "CvImages.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"

namespace cuetrack {

namespace {

bool hasImageExtension(const char* name) {
  const char* dot = std::strrchr(name, '.');
  if (!dot) return false;
  char ext[8] = "";
  for (size_t i = 0; i + 1 < sizeof ext && dot[1 + i]; ++i)
    ext[i] = static_cast<char>(std::tolower(static_cast<unsigned char>(dot[1 + i])));
  return !std::strcmp(ext, "png") || !std::strcmp(ext, "jpg") || !std::strcmp(ext, "jpeg") ||
         !std::strcmp(ext, "ppm") || !std::strcmp(ext, "pgm") || !std::strcmp(ext, "bmp");
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

}  // namespace

ImageFolderReader::ImageFolderReader() : _img(new CvImages) {}
ImageFolderReader::~ImageFolderReader() = default;

void ImageFolderReader::startOpen(const char* dir, const SourceOptions& opt) {
  restart(opt);
  _dir = dir;
  while (_dir.size() > 1 && _dir.back() == '/') _dir.pop_back();
  _name = rec::fileStem(_dir + ".x");
  _rgbFiles.clear();
  _depthFiles.clear();
  _haveIntrinsics = false;
}

bool ImageFolderReader::listImages(const std::string& folder, std::vector<std::string>* out) {
  DIR* d = opendir(folder.c_str());
  if (!d) {
    std::snprintf(_error, sizeof _error, "%s: cannot open folder", folder.c_str());
    return false;
  }
  std::vector<std::string> names;
  while (dirent* e = readdir(d))
    if (e->d_name[0] != '.' && hasImageExtension(e->d_name)) names.emplace_back(e->d_name);
  closedir(d);
  std::sort(names.begin(), names.end());
  out->clear();
  for (auto& n : names) out->push_back(folder + "/" + n);
  return true;
}

bool ImageFolderReader::finishOpen(const std::string& gtPath, GtFormat format) {
  if (_rgbFiles.empty()) {
    std::snprintf(_error, sizeof _error, "%s: no images", _dir.c_str());
    return false;
  }
  return loadGroundTruth(gtPath, format, frameCount(), "frames");
}

uint64_t ImageFolderReader::frameTimeUs(int i) const {
  return static_cast<uint64_t>(std::llround(i * 1e6 / _fps));
}

CameraIntrinsics ImageFolderReader::frameIntrinsics(int widthPx, int heightPx) const {
  return _haveIntrinsics ? _intrinsics : kinectIntrinsicsScaled(widthPx, heightPx);
}

RecordedReader::FrameRead ImageFolderReader::readFrame(int i, FrameSlot& out) {
  if (i >= frameCount()) return FrameRead::End;
  out.hasDepth = false;
  if (!readColour(_rgbFiles[static_cast<size_t>(i)], out)) return FrameRead::Bad;
  if (!_depthFiles.empty() && !readDepth(_depthFiles[static_cast<size_t>(i)], out))
    return FrameRead::Bad;
  return FrameRead::Ok;
}

bool ImageFolderReader::readColour(const std::string& rgbPath, FrameSlot& out) {
  // imread would block on a FIFO and read a device: regular files only.
  if (!rec::isFile(rgbPath.c_str())) {
    std::snprintf(_error, sizeof _error, "%s: not a regular file", rgbPath.c_str());
    return false;
  }
  if (isJpegName(rgbPath) && !jpegHasEnd(rgbPath)) {
    std::snprintf(_error, sizeof _error, "%s: truncated JPEG (no end-of-image marker)",
                  rgbPath.c_str());
    return false;
  }
  if ((_img->bgr = cv::imread(rgbPath, kColourRead)).empty()) {
    std::snprintf(_error, sizeof _error, "%s: cannot decode image (missing, truncated or corrupt)",
                  rgbPath.c_str());
    return false;
  }
  if (_img->bgr.depth() != CV_8U) {
    std::snprintf(_error, sizeof _error, "%s: colour must be 8 bits per channel, not %s",
                  rgbPath.c_str(), depthName(_img->bgr.depth()));
    return false;
  }
  if (_width > 0 && (_img->bgr.cols != _width || _img->bgr.rows != _height)) {
    std::snprintf(_error, sizeof _error, "%s: %dx%d, the sequence is %dx%d", rgbPath.c_str(),
                  _img->bgr.cols, _img->bgr.rows, _width, _height);
    return false;
  }
  if (_depthFiles.empty()) {
    copyColourFit(_img->bgr, *_img, out);  // colour only: a large image is scaled down
  } else if (!copyColour(_img->bgr, _img->rgb, out)) {
    // Depth and intrinsics would have to be scaled with it: RGB-D keeps the working size.
    std::snprintf(_error, sizeof _error, "%s: %dx%d is larger than %dx%d", rgbPath.c_str(),
                  _img->bgr.cols, _img->bgr.rows, kMaxImageWidth, kMaxImageHeight);
    return false;
  }
  if (_haveIntrinsics && (_intrinsics.cx > static_cast<float>(out.rgb.width()) ||
                          _intrinsics.cy > static_cast<float>(out.rgb.height()))) {
    // parseIntrinsics checked fx, fy and cx, cy >= 0; the image size is known only now.
    std::snprintf(_error, sizeof _error,
                  "%s/intrinsics.txt: principal point %g,%g outside the %dx%d image", _dir.c_str(),
                  static_cast<double>(_intrinsics.cx), static_cast<double>(_intrinsics.cy),
                  out.rgb.width(), out.rgb.height());
    return false;
  }
  return true;
}

bool ImageFolderReader::readDepth(const std::string& dPath, FrameSlot& out) {
  if (!rec::isFile(dPath.c_str())) {
    std::snprintf(_error, sizeof _error, "%s: not a regular file", dPath.c_str());
    return false;
  }
  if ((_img->depth = cv::imread(dPath, cv::IMREAD_UNCHANGED)).empty()) {
    std::snprintf(_error, sizeof _error,
                  "%s: cannot decode depth image (missing, truncated or corrupt)", dPath.c_str());
    return false;
  }
  if (_img->depth.type() != CV_16UC1) {
    std::snprintf(_error, sizeof _error,
                  "%s: depth must be 16-bit single-channel, not %s with %d channels", dPath.c_str(),
                  depthName(_img->depth.depth()), _img->depth.channels());
    return false;
  }
  if (_img->depth.cols != out.rgb.width() || _img->depth.rows != out.rgb.height()) {
    std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d",
                  dPath.c_str(), _img->depth.cols, _img->depth.rows, out.rgb.width(),
                  out.rgb.height());
    return false;
  }
  out.depthMm.resize(_img->depth.cols, _img->depth.rows);
  for (int y = 0; y < _img->depth.rows; ++y)
    std::memcpy(out.depthMm.data() + y * _img->depth.cols, _img->depth.ptr(y),
                static_cast<size_t>(_img->depth.cols) * 2);
  out.hasDepth = true;
  return true;
}

}  // namespace cuetrack
