// cuetrack-convert (built by apps/synth/CMakeLists.txt): converts any frame source (see --help) to
// a fakenect recording or an RGB-D folder, or measures how fast a source reads (--bench).
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <memory>

#include "SequenceOut.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/platform/OptionOnce.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitFailed = 1;

FrameSlot gSlot;  // 1.5 MiB: static storage

void usage(FILE* f) {
  std::fprintf(
      f,
      "usage: cuetrack-convert SOURCE --out DIR [--format fakenect|rgbd|otb|avi] [options]\n"
      "       cuetrack-convert SOURCE --bench [options]\n"
      "SOURCE is one of:\n%s"
      "options:\n"
      "  --frames N        at most N frames\n"
      "  --seed S          seed of synthetic scenes\n"
      "  --gt PATH         ground truth overriding the source's own\n"
      "  --skip-bad        skip unreadable or damaged frames (counted) instead of stopping\n"
      "  --bench           read every frame, print frames/s (nothing written)\n"
      "  --force           overwrite an existing .avi and its .gt.txt (folders holding a\n"
      "                    recording are always refused)\n"
      "Outputs are whole or absent: a failed or interrupted run (SIGINT/SIGTERM/SIGHUP)\n"
      "removes the folder it created, or the .avi and .gt.txt it wrote.\n"
      "formats: fakenect (default), rgbd (RGB-D folder), otb (OTB folder, colour),\n"
      "         avi (BoBoT-style MJPG video; --out is the .avi path)\n"
      "exit: 0 ok, 1 read/write failed (stdout too), 2 bad arguments (an option given\n"
      "twice too)\n",
      frameSourceHelp());
}

}  // namespace

int main(int argc, char** argv) {
  cuetrack::platform::ignoreWriteSignals();
  const char* spec = nullptr;
  const char* out = nullptr;
  const char* format = "fakenect";
  bool bench = false, force = false;
  SourceOptions opt;
  cuetrack::platform::OptionOnce once;
  char err[1024] = "";
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a[0] == '-' && !once.first(a, err, sizeof err)) {
      std::fprintf(stderr, "cuetrack-convert: %s\n", err);
      return kExitUsage;
    }
    if (!std::strcmp(a, "--help") || !std::strcmp(a, "-h")) {
      usage(stdout);
      return cuetrack::platform::stdoutWritten("cuetrack-convert") ? 0 : kExitFailed;
    } else if (!std::strcmp(a, "--force")) {
      force = true;
    } else if (!std::strcmp(a, "--out") && hasValue) {
      out = argv[++i];
    } else if (!std::strcmp(a, "--format") && hasValue) {
      format = argv[++i];
    } else if (!std::strcmp(a, "--frames") && hasValue) {
      char* end = nullptr;
      const long v = std::strtol(argv[++i], &end, 10);
      if (end == argv[i] || *end != '\0' || v < 1 || v > 10000000) {
        std::fprintf(stderr, "cuetrack-convert: --frames '%s' is not a positive number\n", argv[i]);
        return kExitUsage;
      }
      opt.maxFrames = static_cast<int>(v);
    } else if (!std::strcmp(a, "--seed") && hasValue) {
      char* end = nullptr;
      errno = 0;
      opt.seed = std::strtoull(argv[++i], &end, 10);
      // strtoull takes "-1" as 2^64-1: only plain digits are a seed.
      if (*argv[i] < '0' || *argv[i] > '9' || end == argv[i] || *end != '\0' || errno != 0) {
        std::fprintf(stderr, "cuetrack-convert: --seed '%s' is not a non-negative whole number\n",
                     argv[i]);
        return kExitUsage;
      }
    } else if (!std::strcmp(a, "--gt") && hasValue) {
      opt.gtPath = argv[++i];
    } else if (!std::strcmp(a, "--skip-bad")) {
      opt.skipBadFrames = true;
    } else if (!std::strcmp(a, "--bench")) {
      bench = true;
    } else if (a[0] == '-' && a[1] == '-') {
      std::fprintf(stderr, "cuetrack-convert: unknown or incomplete argument '%s' (see --help)\n",
                   a);
      return kExitUsage;
    } else if (!spec) {
      spec = a;
    } else {
      std::fprintf(stderr, "cuetrack-convert: more than one SOURCE ('%s', '%s')\n", spec, a);
      return kExitUsage;
    }
  }
  if (!spec || (!bench && !out)) {
    std::fprintf(stderr, "cuetrack-convert: SOURCE and --out (or --bench) are required\n");
    return kExitUsage;
  }
  std::unique_ptr<FrameSource> src = openFrameSource(spec, opt, err, sizeof err);
  if (!src) {
    std::fprintf(stderr, "cuetrack-convert: %s\n", err);
    return kExitFailed;
  }
  if (bench) {
    // Reading only: decode + convert into the slot, as the tracker's input path does.
    int n = 0;
    // Wall and process CPU time: the CPU figure holds on a shared, loaded machine.
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    for (;;) {
      const ReadStatus st = src->next(gSlot);
      if (st == ReadStatus::End) break;
      if (st == ReadStatus::Error) {
        std::fprintf(stderr, "cuetrack-convert: %s\n", src->error());
        return kExitFailed;
      }
      ++n;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf(
        "%s: %d frames %dx%d: wall %.1f frames/s (%.2f ms/frame), cpu %.1f frames/s "
        "(%.2f ms/frame), skipped %d\n",
        src->name(), n, gSlot.rgb.width(), gSlot.rgb.height(), n > 0 ? n / s : 0.0,
        n > 0 ? 1e3 * s / n : 0.0, n > 0 && cpu > 0 ? n / cpu : 0.0, n > 0 ? 1e3 * cpu / n : 0.0,
        src->skippedFrames());
    if (!cuetrack::platform::stdoutWritten("cuetrack-convert")) return kExitFailed;
    return n > 0 ? 0 : kExitFailed;
  }
  auto sink = openSequenceOut(format, out, src->name(), src->nominalFps(), err, sizeof err, force);
  if (!sink) {
    std::fprintf(stderr, "cuetrack-convert: %s\n", err);
    return std::strncmp(err, "unknown format", 14) == 0 ? kExitUsage : kExitFailed;
  }
  cuetrack::platform::installStopSignals();  // an interrupted run removes its partial output
  const int n =
      copySequence(*src, *sink, gSlot, err, sizeof err, cuetrack::platform::stopRequested);
  if (n < 0) {
    std::fprintf(stderr, "cuetrack-convert: %s\n", err);
    return kExitFailed;
  }
  std::printf("cuetrack-convert: wrote %d frames of %s to %s (%s), skipped %d\n", n, spec, out,
              format, src->skippedFrames());
  return cuetrack::platform::stdoutWritten("cuetrack-convert") ? 0 : kExitFailed;
}
