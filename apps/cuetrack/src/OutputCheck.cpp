#include "OutputCheck.hpp"

#include <cstdio>
#include <cstring>

#include "Sources.hpp"
#include "cuetrack/drivers/MediaFiles.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/platform/linux/PathClash.hpp"

namespace cuetrack::app {
namespace {

constexpr int kMaxInputs = 8;
constexpr size_t kPathBytes = 1024;

}  // namespace

bool checkOutputs(const AppOptions& opt, char* err, size_t errLen) {
  platform::NamedPath outputs[3];
  int nOut = 0;
  if (opt.outPath && std::strcmp(opt.outPath, "-") != 0) outputs[nOut++] = {"--out", opt.outPath};
  if (opt.videoPath) outputs[nOut++] = {"--video", opt.videoPath};
  if (opt.snapshotPath) outputs[nOut++] = {"--snapshot", opt.snapshotPath};
  if (nOut == 0) return true;

  static char paths[kMaxInputs][kPathBytes];
  platform::NamedPath inputs[kMaxInputs];
  int nIn = 0;
  const char* spec = opt.source;
  // Generated scenes (synth:, rand:: the shared data it reads is never written) and
  // cameras have no input path an output could clash with.
  if (spec && std::strncmp(spec, "kinect", 6) != 0 && std::strncmp(spec, "synth", 5) != 0 &&
      std::strncmp(spec, "rand:", 5) != 0 && !isCameraSpec(spec)) {
    const bool still = std::strncmp(spec, "still:", 6) == 0;
    if (still || std::strncmp(spec, "pan:", 4) == 0) {
      // pan:RGB,DEPTH,... / still:RGB,DEPTH,...:SCENE@...: the files named, before any ':'.
      const char* s = spec + (still ? 6 : 4);
      while (*s != '\0' && *s != ':' && nIn < kMaxInputs) {
        const size_t n = std::strcspn(s, ",:");
        std::snprintf(paths[nIn], kPathBytes, "%.*s", static_cast<int>(n), s);
        inputs[nIn] = {"--source", paths[nIn]};
        ++nIn;
        s += n;
        if (*s == ',') ++s;
      }
    } else {
      inputs[nIn++] = {"--source", spec};
      // A video's ground truth beside it (NAME.gt.txt or NAME.txt) is an input too; a
      // folder's is inside.
      if (rec::isVideoName(spec)) {
        describeGroundTruth(spec, paths[nIn], kPathBytes);
        inputs[nIn] = {"--source's ground truth", paths[nIn]};
        ++nIn;
      }
    }
  }
  return platform::checkPathClashes(outputs, nOut, inputs, nIn, err, errLen);
}

}  // namespace cuetrack::app
