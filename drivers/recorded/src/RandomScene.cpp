#include "cuetrack/drivers/RandomScene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "CvImages.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/ImageLoaders.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"
#include "cuetrack/drivers/SceneDraw.hpp"
#include "cuetrack/drivers/StillSpecs.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

namespace {

// The stills of ../shared/data/kinect-stills, as its README gives them.
struct StillFile {
  const char* rgb;
  const char* depth;
  float mmPerUnit;
  CameraIntrinsics k;
  const char* label;
};
constexpr CameraIntrinsics kNyu{518.f, 519.f, 325.5f, 253.5f};
constexpr CameraIntrinsics kTumFr1{517.3f, 516.5f, 318.6f, 255.3f};
constexpr StillFile kStills[] = {
    {"nyu-joinmap/color/1.png", "nyu-joinmap/depth/1.pgm", 1.f, kNyu, "nyu1"},
    {"nyu-joinmap/color/2.png", "nyu-joinmap/depth/2.pgm", 1.f, kNyu, "nyu2"},
    {"nyu-joinmap/color/3.png", "nyu-joinmap/depth/3.pgm", 1.f, kNyu, "nyu3"},
    {"nyu-joinmap/color/4.png", "nyu-joinmap/depth/4.pgm", 1.f, kNyu, "nyu4"},
    {"nyu-joinmap/color/5.png", "nyu-joinmap/depth/5.pgm", 1.f, kNyu, "nyu5"},
    {"tum-fr1/1.png", "tum-fr1/1_depth.png", 0.2f, kTumFr1, "tum1"},
    {"tum-fr1/2.png", "tum-fr1/2_depth.png", 0.2f, kTumFr1, "tum2"},
};
constexpr int kNumStills = static_cast<int>(sizeof kStills / sizeof kStills[0]);

using Depth = FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>;

// The development videos (DATA/otb/NAME with img/ and groundtruth_rect.txt), sorted.
std::vector<std::string> otbVideos(const std::string& otbDir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(otbDir, ec)) {
    const std::string dir = e.path().string();
    if (rec::isFile((dir + "/groundtruth_rect.txt").c_str()) &&
        rec::isDirectory((dir + "/img").c_str()))
      names.push_back(dir);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A 64x64 RGB tile: the ground-truth box of frame (draw / videos) of video (draw % videos).
bool realTile(const std::vector<std::string>& videos, uint32_t draw, Rgb8* tile, char* err,
              size_t errLen) {
  const std::string& dir = videos[draw % videos.size()];
  const std::string gtPath = dir + "/groundtruth_rect.txt";
  std::vector<uint8_t> gt;
  if (!rec::readFile(gtPath.c_str(), gt, err, errLen)) return false;
  std::vector<std::array<float, 4>> boxes;
  size_t pos = 0;
  const char* line = nullptr;
  size_t len = 0;
  const char* text = reinterpret_cast<const char*>(gt.data());
  while (rec::nextLine(text, gt.size(), &pos, &line, &len)) {
    float b[4];
    char why[160];
    if (rec::blankLine(line, len) || !rec::parseOtbLine(line, len, b, why, sizeof why)) continue;
    if (b[2] >= 8.f && b[3] >= 8.f)
      boxes.push_back({b[0], b[1], b[2], b[3]});
    else
      boxes.push_back({0.f, 0.f, 0.f, 0.f});
  }
  if (boxes.empty()) {
    std::snprintf(err, errLen, "%s: no box to cut a texture from", gtPath.c_str());
    return false;
  }
  // The first frame at or after the drawn one with a box of at least 8x8 px.
  size_t f = (draw / videos.size()) % boxes.size();
  for (size_t i = 0; i < boxes.size() && boxes[f][2] == 0.f; ++i) f = (f + 1) % boxes.size();
  char name[32];
  std::snprintf(name, sizeof name, "/img/%04zu.jpg", f + 1);
  const cv::Mat img = cv::imread(dir + name, cv::IMREAD_COLOR);
  if (img.empty()) {
    std::snprintf(err, errLen, "%s%s: cannot decode image", dir.c_str(), name);
    return false;
  }
  const std::array<float, 4>& b = boxes[f];
  // OTB boxes are 1-based.
  cv::Rect r(static_cast<int>(b[0]) - 1, static_cast<int>(b[1]) - 1, static_cast<int>(b[2]),
             static_cast<int>(b[3]));
  r &= cv::Rect(0, 0, img.cols, img.rows);
  if (r.width < 4 || r.height < 4) r = cv::Rect(0, 0, img.cols, img.rows);
  cv::Mat small, rgb;
  cv::resize(img(r), small, cv::Size(kTextureSize, kTextureSize), 0, 0, cv::INTER_AREA);
  cv::cvtColor(small, rgb, cv::COLOR_BGR2RGB);
  for (int y = 0; y < kTextureSize; ++y)
    for (int x = 0; x < kTextureSize; ++x) {
      const cv::Vec3b p = rgb.at<cv::Vec3b>(y, x);
      tile[y * kTextureSize + x] = {p[0], p[1], p[2]};
    }
  return true;
}

}  // namespace

struct RandomSceneReader::Data {
  Depth depth[kNumStills];
  FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight> rgb;  // the chosen still's
};

RandomSceneReader::RandomSceneReader() : _data(new Data) {}
RandomSceneReader::~RandomSceneReader() = default;

bool RandomSceneReader::open(const char* spec, const SourceOptions& opt) {
  _error[0] = '\0';
  _scene.reset();
  rec::RandomSpec p;
  if (!rec::parseRandomSpec(spec, &p, _error, sizeof _error)) return false;
  StillView views[kNumStills];
  int numStills = 0;
  std::vector<std::string> videos;
  if (!p.dataDir.empty()) {
    const std::string stills = p.dataDir + "/kinect-stills", otb = p.dataDir + "/otb";
    if (!rec::isDirectory(stills.c_str()) || !rec::isDirectory(otb.c_str())) {
      std::snprintf(_error, sizeof _error,
                    "%s: %s has no kinect-stills/ and otb/ (the shared data)", spec,
                    p.dataDir.c_str());
      return false;
    }
    for (int i = 0; i < kNumStills; ++i) {
      const std::string path = stills + "/" + kStills[i].depth;
      Depth& d = _data->depth[i];
      if (!loadDepthPng16(path.c_str(), d, _error, sizeof _error, kStills[i].mmPerUnit))
        return false;
      views[i] = {d.data(), d.width(), d.height(), kStills[i].k};
    }
    numStills = kNumStills;
    videos = otbVideos(otb);
    if (videos.empty()) {
      std::snprintf(_error, sizeof _error, "%s: %s holds no video with groundtruth_rect.txt", spec,
                    otb.c_str());
      return false;
    }
  }
  SceneDraw d;
  drawScene(p.seed, views, numStills, !videos.empty(), &d);
  SceneSpec& s = d.spec;
  if (opt.maxFrames >= 0 && opt.maxFrames < s.frameCount) s.frameCount = opt.maxFrames;
  _name = s.name;
  if (d.still >= 0) {
    _name += std::string("-") + kStills[d.still].label;
    const std::string path = p.dataDir + "/kinect-stills/" + kStills[d.still].rgb;
    if (!loadColourImage(path.c_str(), _data->rgb, _error, sizeof _error)) return false;
    if (_data->rgb.width() != s.width || _data->rgb.height() != s.height) {
      std::snprintf(_error, sizeof _error, "%s: colour %dx%d does not match its depth %dx%d",
                    path.c_str(), _data->rgb.width(), _data->rgb.height(), s.width, s.height);
      return false;
    }
  }
  if (!start(s, opt.seed, spec)) return false;
  if (d.still >= 0)
    _scene->setBackdrop(_data->rgb.data(), _data->depth[d.still].data(), kStills[d.still].k);
  Rgb8 tile[kTextureSize * kTextureSize];
  for (int i = 0; i < s.numObjects; ++i) {
    if (!d.realTexture[i]) continue;
    if (!realTile(videos, d.textureDraw[i], tile, _error, sizeof _error)) {
      _scene.reset();
      return false;
    }
    _scene->setObjectTexture(i, tile);
  }
  return true;
}

}  // namespace cuetrack
