// Tracker speed on a synthetic scene: median update time (and per-stage split) over a
// run, or, with --icount, the same run without reading any clock so that
// qemu-icount's count for N frames minus the count for 0 frames, / N, is the exact
// per-frame instruction count.
//   cuetrack-trackspeed [--preset 2.1] [--scene moving] [--frames 150] [--particles N]
//                       [--weak M] [--icount] [--hash]
// --hash also prints an FNV-1a hash of every frame's box, confidence and state: two
// builds that print the same hash tracked bit for bit alike.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;

namespace {

class SteadyClock final : public Clock {
 public:
  uint64_t nowUs() const override {
    return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                     std::chrono::steady_clock::now().time_since_epoch())
                                     .count());
  }
};

Tracker tracker;
// Frames are rendered before timing (rendering is not the tracker's cost) and played
// forwards then backwards, so any number of frames keeps a continuous motion.
constexpr int kRendered = 40;
FrameSlot slots[kRendered];
alignas(SyntheticSource) unsigned char sourceStorage[sizeof(SyntheticSource)];
constexpr int kMaxFrames = 2000;
uint32_t totalUs[kMaxFrames], featuresUs[kMaxFrames], predictUs[kMaxFrames], weighUs[kMaxFrames],
    learnUs[kMaxFrames];

double median(uint32_t* v, int n) {
  if (n == 0) return 0;
  std::sort(v, v + n);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Tracks `frames` updates over the rendered frames (forwards then backwards), keeping each
// update's stage times; with hash, an FNV-1a hash of every frame's box, confidence and
// state. The number of frames it learned on.
template <typename FrameOf>
int timeUpdates(int frames, const FrameOf& frameOf, uint64_t* hash) {
  int learned = 0;
  uint64_t h = 14695981039346656037ULL;
  auto mix = [&h](const void* p, std::size_t bytes) {
    const unsigned char* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ULL;
  };
  for (int n = 0; n < frames && !platform::stopRequested(); ++n) {
    const int period = 2 * (kRendered - 1);
    const int k = (n + 1) % period;
    Frame f = frameOf(slots[k < kRendered ? k : period - k]);
    f.timeUs = static_cast<uint64_t>(n + 1) * 33333u;  // time always runs forwards
    const TrackResult r = tracker.update(f);
    learned += r.learned ? 1 : 0;
    if (hash) {
      const float v[5] = {r.box.x, r.box.y, r.box.w, r.box.h, r.confidence};
      mix(v, sizeof v);
      const uint8_t st = static_cast<uint8_t>(r.state);
      mix(&st, 1);
    }
    totalUs[n] = r.timesUs.total;
    featuresUs[n] = r.timesUs.features;
    predictUs[n] = r.timesUs.predict;
    weighUs[n] = r.timesUs.weigh;
    learnUs[n] = r.timesUs.learn;
  }
  if (hash) *hash = h;
  return learned;
}

const char* kExitCodes =
    "exit codes: 0 done, 1 a frame of the scene could not be rendered, the tracker\n"
    "  refused its first box, stdout could not be written, or interrupted (SIGINT,\n"
    "  SIGTERM, SIGHUP), 2 bad command line (an unknown --scene, an option given twice\n"
    "  too; a configuration the tracker refuses)";

constexpr int kExitRun = 1;
constexpr int kExitUsage = 2;  // what the command line asked for cannot run

}  // namespace

int main(int argc, char** argv) {
  platform::installStopSignals();  // first: a stop at any moment ends as --help says
  std::string presetName = "2.1";
  std::string scene = "moving";
  int frames = 150, particles = -1, weak = -1;
  bool icount = false, hash = false, rgbOnly = false;
  Preset preset;
  SceneSpec spec;
  cli::Command cmd("cuetrack-trackspeed",
                   "The tracker's median update time (and its stages) on a synthetic scene.",
                   kExitCodes);
  cmd.option(
      "--preset", "NAME", "1.1-1.4, 2.1-2.5, dcf, best (default 2.1)", [&](const std::string& v) {
        presetName = v;
        return parsePreset(v.c_str(), &preset) ? "" : "unknown (1.1-1.4, 2.1-2.5, dcf, best)";
      });
  cmd.text("--scene", "NAME", "synthetic scene (default moving; cuetrack-synth --list)", &scene);
  cmd.number("--frames", "N",
             "updates to time, 0..1999 (default 150; 0: the set-up, icount's baseline)", 0,
             kMaxFrames - 1, &frames);
  cmd.number("--particles", "N", "particles, 1..2000 (default: the preset's)", 1, kMaxParticles,
             &particles);
  cmd.number("--weak", "M", "weak classifiers, 1..32 (default: the preset's)", 1,
             kMaxWeakClassifiers, &weak);
  cmd.flag("--icount", "read no clock (for qemu-icount: count(N) - count(0), / N)", &icount);
  cmd.flag("--hash", "print an FNV-1a hash of every frame's box, confidence and state", &hash);
  cmd.flag("--rgb-only",
           "drop the scene's depth (best then runs 2D, with the correlation filter; 2.x fail)",
           &rgbOnly);
  if (const int rc = cmd.parse(argc, argv); rc >= 0) return rc;
  parsePreset(presetName.c_str(), &preset);  // checked as it was read
  if (!makeScene(scene.c_str(), &spec)) {
    char names[512];
    listSceneNames(", ", names, sizeof names);
    return cmd.fail(cmd.badValue("--scene", scene, std::string("unknown (scenes: ") + names + ")"));
  }
  spec.frameCount = kRendered;
  SyntheticSource* src = new (sourceStorage) SyntheticSource(spec, 1);
  TrackerConfig cfg = presetConfig(preset);
  if (particles > 0) cfg.numParticles = particles;
  if (weak > 0) cfg.numWeakClassifiers = weak;
  static SteadyClock clock;
  if (const ConfigError e = tracker.configure(cfg, 1, icount ? nullptr : &clock);
      e != ConfigError::None) {
    std::fprintf(stderr, "cuetrack-trackspeed: configuration refused: %s\n", toString(e));
    return kExitUsage;
  }
  for (int i = 0; i < kRendered; ++i) {
    if (src->next(slots[i]) != ReadStatus::Ok) {
      std::fprintf(stderr, "cuetrack-trackspeed: %s\n", src->error());
      return kExitRun;
    }
  }
  // --rgb-only: the frames' views without depth (the rendered depth stays unread).
  auto frameOf = [rgbOnly](const FrameSlot& slot) {
    Frame f = slot.frame();
    if (rgbOnly) f.depthMm = DepthView{};
    return f;
  };
  const InitError e = tracker.init(frameOf(slots[0]), slots[0].groundTruth);
  if (e != InitError::None) {
    std::fprintf(stderr, "cuetrack-trackspeed: %s: the tracker refused the first box: %s\n",
                 scene.c_str(), toString(e));
    return kExitRun;
  }
  uint64_t h = 0;
  const int learned = timeUpdates(frames, frameOf, hash ? &h : nullptr);
  const int n = frames;
  if (platform::stopRequested()) {
    std::fprintf(stderr, "cuetrack-trackspeed: interrupted before the %d updates were timed\n",
                 frames);
    return kExitRun;
  }
  if (hash) std::printf("hash %016llx\n", static_cast<unsigned long long>(h));
  if (icount) {
    std::printf("frames %d learned %d (run under qemu-icount; no clock read)\n", n, learned);
    return platform::stdoutWritten("cuetrack-trackspeed") ? 0 : kExitRun;
  }
  std::printf(
      "preset %s%s scene %s %dx%d frames %d particles %d weak %d learned %d\n"
      "median update %.0f us (features %.0f, predict %.0f, weigh %.0f, learn %.0f); "
      "tracker sizeof %zu B\n",
      presetName.c_str(), rgbOnly ? " (rgb only)" : "", scene.c_str(), spec.width, spec.height, n,
      cfg.numParticles, cfg.numWeakClassifiers, learned, median(totalUs, n), median(featuresUs, n),
      median(predictUs, n), median(weighUs, n), median(learnUs, n), sizeof(Tracker));
  return platform::stdoutWritten("cuetrack-trackspeed") ? 0 : kExitRun;
}
