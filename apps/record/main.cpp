// cuetrack-record: Kinect -> fakenect recording (INDEX.txt, r-*.ppm, d-*.pgm) or RGB-D
// folder (host builds with OpenCV), with a frame-count or duration limit and a progress
// line. Exit codes are in --help (RecordOptions.cpp).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "RecordOptions.hpp"
#include "cuetrack/cli/OutputGuard.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/KinectSource.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#if defined(CUETRACK_RECORD_HAVE_RGBD)
#include "cuetrack/drivers/OpenCvSources.hpp"
#endif

using namespace cuetrack;

namespace {

// Large: static storage, never the stack.
KinectSource gKinect;
FrameSlot gSlot;

// The chosen output format's writer (both share open/write/close/error).
class Output {
 public:
  bool open(record::Format format, const char* dir) {
    _format = format;
    if (format == record::Format::Fakenect) return _fakenect.open(dir);
#if defined(CUETRACK_RECORD_HAVE_RGBD)
    return _rgbd.open(dir);
#else
    _unsupported = true;
    return false;
#endif
  }
  bool write(const FrameSlot& f) {
#if defined(CUETRACK_RECORD_HAVE_RGBD)
    if (_format == record::Format::Rgbd) return _rgbd.write(f);
#endif
    return _fakenect.write(f);
  }
  bool close() {
#if defined(CUETRACK_RECORD_HAVE_RGBD)
    if (_format == record::Format::Rgbd) return _rgbd.close();
#endif
    return _fakenect.close();
  }
  const char* error() const {
    if (_unsupported) return "--format rgbd needs a host build with OpenCV (this build has none)";
#if defined(CUETRACK_RECORD_HAVE_RGBD)
    if (_format == record::Format::Rgbd) return _rgbd.error();
#endif
    return _fakenect.error();
  }

 private:
  record::Format _format = record::Format::Fakenect;
  bool _unsupported = false;
  FakenectWriter _fakenect;
#if defined(CUETRACK_RECORD_HAVE_RGBD)
  RgbdFolderWriter _rgbd;
#endif
};
Output gWriter;

int listDevices() {
  char err[160];
  const int n = countKinects(err, sizeof err);
  if (n < 0) {
    std::fprintf(stderr, "cuetrack-record: %s\n", err);
    return record::kExitDevice;
  }
  std::printf("%d Kinect%s found\n", n, n == 1 ? "" : "s");
  if (n > 0 && !kinectReplayLibraryLoaded()) {
    static char serials[16][kKinectSerialLen];
    const int m = listKinectSerials(serials, 16, err, sizeof err);
    for (int i = 0; i < m; ++i) std::printf("  #%d serial %s\n", i, serials[i]);
  }
  return platform::stdoutWritten("cuetrack-record") ? record::kExitOk : record::kExitOutput;
}

platform::MonotonicClock gClock;
uint64_t gStartUs = 0;

// Wall-clock frames/s tells whether the output keeps up (a fakenect recording is
// 1.5 MB per frame: 46 MB/s at 30 Hz, more than many SD cards write).
void progress(const record::Options& opt, int frames, double seconds, bool final) {
  const KinectStats s = gKinect.stats();
  char limit[32] = "";
  if (opt.maxFrames > 0) std::snprintf(limit, sizeof limit, "/%d", opt.maxFrames);
  const double wallS = static_cast<double>(gClock.nowUs() - gStartUs) / 1e6;
  std::fprintf(stderr,
               "\rrecording %s: %d%s frames, %.1f s, %.1f fps, dropped %llu, unpaired %llu%s",
               opt.outDir.c_str(), frames, limit, seconds, wallS > 0.0 ? frames / wallS : 0.0,
               static_cast<unsigned long long>(s.dropped),
               static_cast<unsigned long long>(s.unpaired), final ? "\n" : "   ");
}

}  // namespace

int main(int argc, char** argv) {
  platform::installStopSignals();  // first: a stop at any moment ends as --help says
  record::Options opt;
  if (const int rc = record::parse(argc, argv, &opt); rc >= 0) return rc;
  if (opt.list) return listDevices();

#if !defined(CUETRACK_RECORD_HAVE_RGBD)
  if (opt.format == record::Format::Rgbd) {
    std::fprintf(stderr, "cuetrack-record: --format rgbd needs a host build with OpenCV\n");
    return record::kExitUsage;
  }
#endif
  // The one output guard of every tool: a replayed recording (the fakenect library reads
  // FAKENECT_PATH) is an input; --out may be neither it nor inside it.
  cli::OutputGuard guard;
  if (const char* replay = std::getenv("FAKENECT_PATH")) guard.input("FAKENECT_PATH", replay);
  guard.outputFolder("--out", opt.outDir);
  if (std::string clash; !guard.check(&clash)) {
    std::fprintf(stderr, "cuetrack-record: %s\n", clash.c_str());
    return record::kExitUsage;
  }
  opt.kinect.stopRequested = &platform::stopRequested;
  if (!gKinect.open(opt.kinect)) {
    std::fprintf(stderr, "cuetrack-record: %s\n", gKinect.error());
    return record::kExitDevice;
  }
  if (!opt.quiet)
    std::fprintf(stderr, "cuetrack-record: %s, streams %s, USB load %.1f MB/s%s\n", gKinect.name(),
                 toString(gKinect.streams()), kinectUsbLoadMBps(gKinect.streams()),
                 gKinect.streams() == KinectStreams::Both
                     ? " (Pi-class boards carry ~15-20 MB/s: see docs/kinect.md if frames drop)"
                     : "");
  if (!gWriter.open(opt.format, opt.outDir.c_str())) {
    std::fprintf(stderr, "cuetrack-record: %s\n", gWriter.error());
    gKinect.close();
    return record::kExitOutput;
  }

  gStartUs = gClock.nowUs();
  int frames = 0;
  double seconds = 0.0;
  uint64_t lastProgressUs = 0;
  int exitCode = record::kExitOk;
  for (;;) {
    if (opt.maxFrames > 0 && frames >= opt.maxFrames) break;
    const ReadStatus st = gKinect.next(gSlot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) {
      if (!opt.quiet) progress(opt, frames, seconds, true);
      std::fprintf(stderr, "cuetrack-record: %s\n", gKinect.error());
      exitCode = record::kExitDevice;
      break;
    }
    // Duration on the camera clock: deterministic, and what the recording will replay.
    seconds = static_cast<double>(gSlot.timeUs) / 1e6;
    if (opt.maxSeconds > 0.0 && seconds >= opt.maxSeconds) break;
    if (!gWriter.write(gSlot)) {
      if (!opt.quiet) progress(opt, frames, seconds, true);
      std::fprintf(stderr, "cuetrack-record: %s\n", gWriter.error());
      exitCode = record::kExitOutput;
      break;
    }
    ++frames;
    if (!opt.quiet && (frames == 1 || gSlot.timeUs - lastProgressUs >= 500000)) {
      lastProgressUs = gSlot.timeUs;
      progress(opt, frames, seconds, false);
    }
  }
  gKinect.close();
  if (!gWriter.close() && exitCode == record::kExitOk) {
    std::fprintf(stderr, "cuetrack-record: %s\n", gWriter.error());
    exitCode = record::kExitOutput;
  }
  if (!opt.quiet) progress(opt, frames, seconds, true);
  if (exitCode == record::kExitOk && frames == 0) {
    std::fprintf(stderr, "cuetrack-record: no frame recorded\n");
    exitCode = record::kExitDevice;
  }
  return exitCode;
}
