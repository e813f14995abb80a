// cuetrack-synth: writes a synthetic RGB-D scene with exact ground truth as a
// fakenect recording or an RGB-D folder.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "SequenceOut.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#include "cuetrack/platform/OptionOnce.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitFailed = 1;

FrameSlot gSlot;  // 1.5 MiB: static storage

void usage(FILE* f) {
  std::fprintf(f,
               "usage: cuetrack-synth --scene NAME --out DIR [--format fakenect|rgbd|otb|avi]\n"
               "                      [--frames N] [--seed S] [--size WxH] [--force]\n"
               "       cuetrack-synth --list\n"
               "Writes a synthetic RGB-D sequence with exact ground truth (groundtruth.txt,\n"
               "BoBoT format) as a fakenect recording (default; INDEX.txt, r-/d-/a- files)\n"
               "or an RGB-D folder (rgb/, depth/ 16-bit PNG mm, intrinsics.txt; needs OpenCV);\n"
               "otb (img/*.jpg + groundtruth_rect.txt) and avi (MJPG video + .gt.txt, --out is\n"
               "the .avi path) are colour only, for the RGB benchmarks' formats (need OpenCV).\n"
               "  --scene NAME   one of --list (default frames: 150 at 30 fps)\n"
               "  --frames N     number of frames (1..100000)\n"
               "  --seed S       sensor-noise seed (same seed, same bytes)\n"
               "  --size WxH     image size (default 640x480, at most 640x480)\n"
               "  --force        overwrite an existing .avi and its .gt.txt (folders holding a\n"
               "                 recording are always refused)\n"
               "Outputs are whole or absent: a failed or interrupted run (SIGINT/SIGTERM/SIGHUP)\n"
               "removes the folder it created, or the .avi and .gt.txt it wrote.\n"
               "exit: 0 ok, 1 write failed (stdout too), 2 bad arguments (an option given twice\n"
               "too)\n");
}

bool parseInt(const char* s, long lo, long hi, long* out) {
  char* end = nullptr;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || v < lo || v > hi) return false;
  *out = v;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  cuetrack::platform::ignoreWriteSignals();
  const char* scene = nullptr;
  const char* out = nullptr;
  const char* format = "fakenect";
  long frames = -1, width = 640, height = 480;
  unsigned long long seed = 1;
  bool force = false;
  cuetrack::platform::OptionOnce once;
  char err[600] = "";
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a[0] == '-' && !once.first(a, err, sizeof err)) {
      std::fprintf(stderr, "cuetrack-synth: %s\n", err);
      return kExitUsage;
    }
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      usage(stdout);
      return cuetrack::platform::stdoutWritten("cuetrack-synth") ? 0 : kExitFailed;
    } else if (!std::strcmp(a, "--list")) {
      for (int k = 0; k < sceneCount(); ++k) std::printf("%s\n", sceneName(k));
      return cuetrack::platform::stdoutWritten("cuetrack-synth") ? 0 : kExitFailed;
    } else if (!std::strcmp(a, "--force")) {
      force = true;
    } else if (!std::strcmp(a, "--scene") && hasValue) {
      scene = argv[++i];
    } else if (!std::strcmp(a, "--out") && hasValue) {
      out = argv[++i];
    } else if (!std::strcmp(a, "--format") && hasValue) {
      format = argv[++i];
    } else if (!std::strcmp(a, "--frames") && hasValue) {
      if (!parseInt(argv[++i], 1, 100000, &frames)) {
        std::fprintf(stderr, "cuetrack-synth: --frames '%s' is not a number in 1..100000\n",
                     argv[i]);
        return kExitUsage;
      }
    } else if (!std::strcmp(a, "--seed") && hasValue) {
      char* end = nullptr;
      errno = 0;
      seed = std::strtoull(argv[++i], &end, 10);
      // strtoull takes "-1" as 2^64-1: only plain digits are a seed.
      if (*argv[i] < '0' || *argv[i] > '9' || end == argv[i] || *end != '\0' || errno != 0) {
        std::fprintf(stderr, "cuetrack-synth: --seed '%s' is not a non-negative whole number\n",
                     argv[i]);
        return kExitUsage;
      }
    } else if (!std::strcmp(a, "--size") && hasValue) {
      const char* s = argv[++i];
      const char* x = std::strchr(s, 'x');
      char w[16] = "";
      if (!x || x - s >= 15) {
        std::fprintf(stderr, "cuetrack-synth: --size '%s' is not WxH\n", s);
        return kExitUsage;
      }
      std::memcpy(w, s, static_cast<size_t>(x - s));
      if (!parseInt(w, 8, kMaxImageWidth, &width) ||
          !parseInt(x + 1, 8, kMaxImageHeight, &height)) {
        std::fprintf(stderr, "cuetrack-synth: --size '%s' outside 8x8..%dx%d\n", s, kMaxImageWidth,
                     kMaxImageHeight);
        return kExitUsage;
      }
    } else {
      std::fprintf(stderr, "cuetrack-synth: unknown or incomplete argument '%s' (see --help)\n", a);
      return kExitUsage;
    }
  }
  if (!scene || !out) {
    std::fprintf(stderr, "cuetrack-synth: --scene and --out are required (see --help)\n");
    return kExitUsage;
  }
  SceneSpec spec;
  if (!makeScene(scene, &spec)) {
    std::fprintf(stderr, "cuetrack-synth: unknown scene '%s' (--list shows them)\n", scene);
    return kExitUsage;
  }
  if (frames > 0) spec.frameCount = static_cast<int>(frames);
  spec.width = static_cast<int>(width);
  spec.height = static_cast<int>(height);
  auto src = std::make_unique<SyntheticSource>(spec, seed);
  auto sink = openSequenceOut(format, out, scene, src->nominalFps(), err, sizeof err, force);
  if (!sink) {
    std::fprintf(stderr, "cuetrack-synth: %s\n", err);
    return std::strncmp(err, "unknown format", 14) == 0 ? kExitUsage : kExitFailed;
  }
  cuetrack::platform::installStopSignals();  // an interrupted run removes its partial output
  const int n =
      copySequence(*src, *sink, gSlot, err, sizeof err, cuetrack::platform::stopRequested);
  if (n < 0) {
    std::fprintf(stderr, "cuetrack-synth: %s\n", err);
    return kExitFailed;
  }
  std::printf("cuetrack-synth: wrote %d frames of '%s' (%dx%d, seed %llu) to %s (%s)\n", n, scene,
              spec.width, spec.height, seed, out, format);
  return cuetrack::platform::stdoutWritten("cuetrack-synth") ? 0 : kExitFailed;
}
