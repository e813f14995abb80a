#include "cuetrack/drivers/OpenSource.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/MediaFiles.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"
#include "cuetrack/drivers/SceneDraw.hpp"
#include "cuetrack/drivers/StillSpecs.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#if CUETRACK_HAVE_OPENCV
#include "cuetrack/drivers/BobotVideo.hpp"
#include "cuetrack/drivers/CameraSource.hpp"
#include "cuetrack/drivers/OtbFolder.hpp"
#include "cuetrack/drivers/RandomScene.hpp"
#include "cuetrack/drivers/RgbdFolder.hpp"
#include "cuetrack/drivers/StillPan.hpp"
#include "cuetrack/drivers/StillScene.hpp"
#endif

namespace cuetrack {

namespace {

// A generated scene, cut to opt.maxFrames; nullptr with its error in err.
std::unique_ptr<FrameSource> sceneSource(SceneSpec s, const SourceOptions& opt, char* err,
                                         size_t errLen) {
  if (opt.maxFrames >= 0 && opt.maxFrames < s.frameCount) s.frameCount = opt.maxFrames;
  auto src = std::make_unique<SyntheticSource>(s, opt.seed);
  if (src->error()[0]) {
    std::snprintf(err, errLen, "%s", src->error());
    return nullptr;
  }
  return src;
}

std::unique_ptr<FrameSource> openSynth(const std::string& spec, const SourceOptions& opt, char* err,
                                       size_t errLen) {
  // synth:<scene>[:frames]
  std::string rest = spec.substr(6);
  std::string scene = rest;
  int frames = -1;
  const size_t colon = rest.find(':');
  if (colon != std::string::npos) {
    scene = rest.substr(0, colon);
    const std::string n = rest.substr(colon + 1);
    if (!rec::parseFrameCount(n.c_str(), &frames)) {
      std::snprintf(err, errLen, "%s: frame count '%s' is not a number in 1..%ld", spec.c_str(),
                    n.c_str(), rec::kMaxSpecFrames);
      return nullptr;
    }
  }
  SceneSpec s;
  char why[512];
  if (!makeScene(scene.c_str(), &s, why, sizeof why)) {
    std::snprintf(err, errLen, "%s: %s", spec.c_str(), why);
    return nullptr;
  }
  if (frames > 0) s.frameCount = frames;
  return sceneSource(s, opt, err, errLen);
}

// rand:SEED: the drawn scene in the generated room, any build; rand:SEED:DATA over the
// real stills and video textures (RandomSceneReader, OpenCV).
std::unique_ptr<FrameSource> openRandom(const char* spec, const SourceOptions& opt, char* err,
                                        size_t errLen) {
  rec::RandomSpec p;
  if (!rec::parseRandomSpec(spec, &p, err, errLen)) return nullptr;
  if (!p.dataDir.empty()) {
#if CUETRACK_HAVE_OPENCV
    auto r = std::make_unique<RandomSceneReader>();
    if (!r->open(spec, opt)) {
      std::snprintf(err, errLen, "%s", r->error());
      return nullptr;
    }
    return r;
#else
    std::snprintf(err, errLen,
                  "%s: real stills and textures need a host build with OpenCV "
                  "(rand:%llu alone draws the generated room)",
                  spec, p.seed);
    return nullptr;
#endif
  }
  SceneDraw d;
  drawScene(p.seed, nullptr, 0, false, &d);
  return sceneSource(d.spec, opt, err, errLen);
}

template <typename Reader>
std::unique_ptr<FrameSource> openWith(const char* path, const SourceOptions& opt, char* err,
                                      size_t errLen) {
  auto r = std::make_unique<Reader>();
  if (!r->open(path, opt)) {
    std::snprintf(err, errLen, "%s", r->error());
    return nullptr;
  }
  return r;
}

[[maybe_unused]] std::unique_ptr<FrameSource> needsOpenCv(const char* path, const char* format,
                                                          char* err, size_t errLen) {
  std::snprintf(err, errLen, "%s: %s needs a host build with OpenCV (this build has none)", path,
                format);
  return nullptr;
}

#if CUETRACK_HAVE_OPENCV
std::unique_ptr<FrameSource> openCamera(const char* spec, char* err, size_t errLen) {
  auto c = std::make_unique<CameraSource>();
  if (!c->open(spec)) {
    std::snprintf(err, errLen, "%s", c->error());
    return nullptr;
  }
  return c;
}
#endif

}  // namespace

bool isCameraSpec(const char* spec) {
  return spec && (std::strcmp(spec, "camera") == 0 || std::strncmp(spec, "camera:", 7) == 0);
}

bool findDefaultCamera(char* device, size_t deviceLen) {
#if CUETRACK_HAVE_OPENCV
  std::string d;
  if (!findCamera(&d)) return false;
  std::snprintf(device, deviceLen, "%s", d.c_str());
  return true;
#else
  (void)device;
  (void)deviceLen;
  return false;
#endif
}

bool frameSourcesHaveOpenCv() {
#if CUETRACK_HAVE_OPENCV
  return true;
#else
  return false;
#endif
}

const char* frameSourceHelp() {
  return "  synth:<scene>[:frames]   synthetic RGB-D scene (cuetrack-synth --list)\n"
         "  rand:SEED[:DATA]         a synthetic RGB-D scene drawn from SEED; with DATA (the\n"
         "                           shared data folder) over real Kinect stills, with\n"
         "                           textures cut from real videos              [OpenCV]\n"
         "  <dir>/ with INDEX.txt    fakenect recording (+ groundtruth.txt, BoBoT format)\n"
         "  <dir>/ with rgb/ depth/  RGB-D folder (+ groundtruth.txt, intrinsics.txt)  [OpenCV]\n"
         "  <dir>/ with img/         OTB folder (+ groundtruth_rect.txt)                [OpenCV]\n"
         "  <dir>/ of images         image folder (+ groundtruth_rect.txt)              [OpenCV]\n"
         "  <file>.avi|.mp4|.mkv|.mov|...  a video (+ <file>.gt.txt BoBoT, or <file>.txt\n"
         "                           OTB x,y,w,h); any size, scaled down to 640x480     [OpenCV]\n"
         "  camera[:N|:/dev/videoN]  a V4L2/UVC camera, colour only                     [OpenCV]\n"
         "  pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames]\n"
         "                           a real RGB-D still panned (box in px; 150 frames)  [OpenCV]\n"
         "  still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]\n"
         "                           a synth: scene's objects in a real RGB-D still, the\n"
         "                           target at pixel u,v, gapMm before the surface  [OpenCV]\n";
}

std::unique_ptr<FrameSource> openFrameSource(const char* spec, const SourceOptions& opt, char* err,
                                             size_t errLen) {
  if (!spec || !*spec) {
    std::snprintf(err, errLen, "no frame source given");
    return nullptr;
  }
  const std::string s = spec;
  if (s.rfind("synth:", 0) == 0) return openSynth(s, opt, err, errLen);
  if (s.rfind("rand:", 0) == 0) return openRandom(spec, opt, err, errLen);
  if (rec::pathTooLong(spec, err, errLen)) return nullptr;
  if (isCameraSpec(spec)) {
#if CUETRACK_HAVE_OPENCV
    return openCamera(spec, err, errLen);
#else
    return needsOpenCv(spec, "a V4L2 camera", err, errLen);
#endif
  }
  if (s.rfind("pan:", 0) == 0) {
#if CUETRACK_HAVE_OPENCV
    return openWith<StillPanReader>(spec, opt, err, errLen);
#else
    return needsOpenCv(spec, "a panned still (PNG)", err, errLen);
#endif
  }
  if (s.rfind("still:", 0) == 0) {
#if CUETRACK_HAVE_OPENCV
    return openWith<StillSceneReader>(spec, opt, err, errLen);
#else
    return needsOpenCv(spec, "a scene in a real still (PNG)", err, errLen);
#endif
  }
  if (rec::isDirectory(spec)) {
    if (rec::isFile((s + "/INDEX.txt").c_str()))
      return openWith<FakenectReader>(spec, opt, err, errLen);
    const bool rgbd =
        rec::isDirectory((s + "/rgb").c_str()) && rec::isDirectory((s + "/depth").c_str());
    const bool otb = rec::isDirectory((s + "/img").c_str()) || rec::folderHoldsImages(spec);
#if CUETRACK_HAVE_OPENCV
    if (rgbd) return openWith<RgbdFolderReader>(spec, opt, err, errLen);
    if (otb) return openWith<OtbFolderReader>(spec, opt, err, errLen);
#else
    if (rgbd) return needsOpenCv(spec, "an RGB-D folder (PNG)", err, errLen);
    if (otb) return needsOpenCv(spec, "an OTB or image folder (JPEG, PNG)", err, errLen);
#endif
    std::snprintf(err, errLen,
                  "%s: not a recording (no INDEX.txt, rgb/ + depth/, img/ or images inside)", spec);
    return nullptr;
  }
  if (rec::isVideoName(spec)) {
    if (!rec::isFile(spec)) {
      std::snprintf(err, errLen, "%s: %s", spec,
                    rec::exists(spec) ? "not a regular file" : "no such file");
      return nullptr;
    }
#if CUETRACK_HAVE_OPENCV
    return openWith<BobotVideoReader>(spec, opt, err, errLen);
#else
    return needsOpenCv(spec, "a video", err, errLen);
#endif
  }
  if (!rec::exists(spec))
    std::snprintf(err, errLen, "%s: no such file or folder", spec);
  else if (!rec::isFile(spec))
    std::snprintf(err, errLen, "%s: not a recording (a device, FIFO or socket)", spec);
  else
    std::snprintf(err, errLen, "%s: unknown format (expected %s, a recording folder or synth:)",
                  spec, rec::videoExtensionsText());
  return nullptr;
}

}  // namespace cuetrack
