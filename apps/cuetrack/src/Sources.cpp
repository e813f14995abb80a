#include "Sources.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>

#include "Options.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#if defined(CUETRACK_HAVE_KINECT)
#include "cuetrack/drivers/KinectSource.hpp"
#endif
#include "cuetrack/drivers/MediaFiles.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

namespace cuetrack::app {
namespace {

char gDefaultWhy[512] = "";   // why openSource(nullptr) chose what it chose
char gDefaultSpec[160] = "";  // and what, as --source would name it (empty: synth)

// Recordings, videos and cameras: the project's one factory. Board builds have no OpenCV,
// so there it opens fakenect recordings only (and says so for other formats). One
// allocation, at start.
FrameSource* openThroughFactory(const char* spec, uint64_t seed, bool skipBadFrames, char* err,
                                size_t errLen, const char* gtPath = nullptr,
                                bool gtOptional = false) {
  SourceOptions options;
  options.seed = seed;
  options.skipBadFrames = skipBadFrames;
  options.gtPath = gtPath;
  options.groundTruthOptional = gtOptional;
  static std::unique_ptr<FrameSource> recorded;
  recorded = openFrameSource(spec, options, err, errLen);
  return recorded.get();
}

// No Kinect: a V4L2 camera when one opens (gDefaultWhy says so), else nullptr.
FrameSource* openDefaultCamera(const char* noKinect, uint64_t seed, char* err, size_t errLen) {
  char device[128];
  if (!findDefaultCamera(device, sizeof device)) return nullptr;
  std::snprintf(gDefaultSpec, sizeof gDefaultSpec, "camera:%s", device);
  std::snprintf(gDefaultWhy, sizeof gDefaultWhy,
                "%s, the camera plugged in (%.200s; --source to choose another)", gDefaultSpec,
                noKinect);
  return openThroughFactory(gDefaultSpec, seed, false, err, errLen);
}

FrameSource* openSynth(const char* scene, uint64_t seed, int frames, char* err, size_t errLen) {
  SceneSpec spec;
  char why[512];
  if (!makeScene(scene, &spec, why, sizeof why)) {
    std::snprintf(err, errLen, "synth:%s: %s", scene, why);
    return nullptr;
  }
  if (frames > 0) spec.frameCount = frames;
  static SyntheticSource source(spec, seed);  // ~2.6 MiB, built once on first use
  return &source;
}

#if defined(CUETRACK_HAVE_KINECT)
bool gKinectOpened = false;  // the source, however wrapped (--wait-camera), is the Kinect

KinectSource& kinect() {
  static KinectSource source;  // ~4.6 MiB of frame buffers
  return source;
}

FrameSource* openKinect(KinectStreams streams, char* err, size_t errLen) {
  KinectOptions options;
  options.streams = streams;
  options.stopRequested = &platform::stopRequested;  // SIGINT/SIGTERM end a wait for frames
  if (!kinect().open(options)) {
    std::snprintf(err, errLen, "%s", kinect().error());
    return nullptr;
  }
  gKinectOpened = true;
  return &kinect();
}
#endif

}  // namespace

FrameSource* openSource(const char* spec, uint64_t seed, int frames, char* err, size_t errLen,
                        bool skipBadFrames, const char* gtPath, bool gtOptional) {
  if (spec == nullptr) {
#if defined(CUETRACK_HAVE_KINECT)
    char why[160] = "";
    const int kinects = countKinects(why, sizeof why);
    if (kinects > 0) {
      std::snprintf(gDefaultWhy, sizeof gDefaultWhy,
                    "kinect, the Kinect plugged in (--source to choose another)");
      return openKinect(KinectStreams::Both, err, errLen);
    }
    char noKinect[200];
    std::snprintf(noKinect, sizeof noKinect, "%s%s",
                  kinects < 0 ? "Kinect unusable: " : "no Kinect found", kinects < 0 ? why : "");
#else
    const char* noKinect = "this build has no Kinect driver";
#endif
    if (FrameSource* camera = openDefaultCamera(noKinect, seed, err, errLen)) return camera;
    if (gDefaultSpec[0] != '\0') return nullptr;  // a camera was there but failed: err says why
    std::snprintf(gDefaultWhy, sizeof gDefaultWhy,
                  "synth:%s, a generated scene (%s, %s; --source "
                  "kinect|camera|synth:SCENE|PATH to choose)",
                  kDefaultScene, noKinect,
                  frameSourcesHaveOpenCv() ? "no camera found" : "no camera support in this build");
    return openSynth(kDefaultScene, seed, frames, err, errLen);
  }
  if (std::strcmp(spec, "kinect") == 0 || std::strncmp(spec, "kinect:", 7) == 0) {
#if defined(CUETRACK_HAVE_KINECT)
    // Options accepted only kinect, kinect:both and kinect:colour.
    const bool colourOnly = std::strcmp(spec, "kinect:colour") == 0;
    return openKinect(colourOnly ? KinectStreams::ColourOnly : KinectStreams::Both, err, errLen);
#else
    std::snprintf(err, errLen, "kinect: this build has no Kinect driver (libfreenect missing)");
    return nullptr;
#endif
  }
  if (std::strcmp(spec, "synth") == 0) return openSynth(kDefaultScene, seed, frames, err, errLen);
  // synth:SCENE here (runs for --frames); synth:SCENE:N goes to the shared factory below.
  if (std::strncmp(spec, "synth:", 6) == 0 && !std::strchr(spec + 6, ':')) {
    return openSynth(spec + 6, seed, frames, err, errLen);
  }
  return openThroughFactory(spec, seed, skipBadFrames, err, errLen, gtPath, gtOptional);
}

void describeSourceChoice(const char* spec, char* out, size_t outLen) {
  if (spec == nullptr && gDefaultWhy[0] != '\0') {
    std::snprintf(out, outLen, "%s", gDefaultWhy);
  } else {
    std::snprintf(out, outLen, "%s", spec ? spec : "default");
  }
}

bool kinectSupported() {
#if defined(CUETRACK_HAVE_KINECT)
  return true;
#else
  return false;
#endif
}

void describeGroundTruth(const char* spec, char* out, size_t outLen, const char* gtPath) {
  if (gtPath) {
    std::snprintf(out, outLen, "%s", gtPath);
    return;
  }
  if (!spec && gDefaultSpec[0] != '\0') spec = gDefaultSpec;  // the default chose a camera
  if (!spec || std::strncmp(spec, "kinect", 6) == 0 || std::strncmp(spec, "synth", 5) == 0 ||
      std::strncmp(spec, "pan:", 4) == 0 || std::strncmp(spec, "still:", 6) == 0 ||
      std::strncmp(spec, "rand:", 5) == 0 || isCameraSpec(spec)) {
    if (spec) {
      std::snprintf(out, outLen, "%s ground truth", spec);
    } else {
      std::snprintf(out, outLen, "synth:%s ground truth", kDefaultScene);
    }
    return;
  }
  const size_t n = std::strlen(spec);
  if (rec::isVideoName(spec)) {  // NAME.gt.txt (BoBoT) or NAME.txt (OTB)
    std::snprintf(out, outLen, "%s", rec::videoGroundTruthPath(spec).c_str());
    return;
  }
  // A folder: fakenect (INDEX.txt) and RGB-D (rgb/) folders read groundtruth.txt, OTB
  // (img/) and image folders groundtruth_rect.txt: the file the reader looks for.
  int dirLen = static_cast<int>(n);
  while (dirLen > 1 && spec[dirLen - 1] == '/') --dirLen;
  std::snprintf(out, outLen, "%.*s/INDEX.txt", dirLen, spec);
  const bool fakenect = ::access(out, F_OK) == 0;
  std::snprintf(out, outLen, "%.*s/rgb", dirLen, spec);
  const bool rgbd = ::access(out, F_OK) == 0;
  std::snprintf(out, outLen, "%.*s/%s", dirLen, spec,
                fakenect || rgbd ? "groundtruth.txt" : "groundtruth_rect.txt");
}

uint64_t droppedFrames(const FrameSource& source) {
  uint64_t n = static_cast<uint64_t>(source.skippedFrames());
#if defined(CUETRACK_HAVE_KINECT)
  if (gKinectOpened) n += kinect().stats().dropped;
#endif
  return n;
}

}  // namespace cuetrack::app
