// The cuetrack program as a few named steps: check the command line, open the source,
// resolve the start box, open the outputs, wire the pipeline, run the loop, close the
// outputs and print the summary. runCuetrack() only calls them in order; each says why
// it would end the run, with the exit code the tests and the service rely on.
#include "App.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "CommandLineCheck.hpp"
#include "Options.hpp"
#include "PacedSource.hpp"
#include "Pipeline.hpp"
#include "PrefetchedSource.hpp"
#include "RunReport.hpp"
#include "RunSummary.hpp"
#include "SerialLink.hpp"
#include "Sources.hpp"
#include "View.hpp"
#include "WaitingSource.hpp"
#include "cuetrack/platform/linux/FdTrackSink.hpp"
#include "cuetrack/platform/linux/KeyFile.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#include "cuetrack/platform/linux/StderrReporter.hpp"
#include "cuetrack/platform/linux/UdpSocket.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"

namespace cuetrack::app {
namespace {

// What the run writes to (static storage, like every big object of the app).
struct Outputs {
  platform::FdTrackSink fileSink;
  platform::FdTrackSink stdoutSink;
  platform::SerialPort port;
  platform::UdpSocket udp;
  VideoOut video;
  bool videoOk = false;                 // --video given and no write failed yet
  bool stdoutIsTerminal = false;        // no line per frame there unless --stdout
  platform::TrackLink* link = nullptr;  // serial or MAVLink, if any
};

// The target comes from the user (--box, --select, --snapshot) or --no-gt drops the ground
// truth: one beside the recording that does not fit is a warning, not a failed run.
bool groundTruthOptional(const AppOptions& opt) {
  return opt.hasBox || opt.select || opt.snapshotPath || !opt.useGroundTruth;
}

// The frame source; nullptr once the reason is reported. With --wait-camera the camera
// may come later: the run starts without it (outputs open, the link served), and next()
// looks for it every second.
FrameSource* openFrameSource(AppOptions& opt, const Clock& clock, platform::Sleeper& sleeper,
                             platform::Reporter& reporter) {
  if (opt.waitCamera) {
    static WaitingSource waiting(
        [](void* ctx, char* e, size_t n) {
          const AppOptions& o = *static_cast<const AppOptions*>(ctx);
          return openSource(o.source, o.seed, o.frames, e, n, o.skipBadFrames, o.gtPath,
                            groundTruthOptional(o));
        },
        &opt, clock, sleeper, reporter, &platform::stopRequested);
    waiting.tryOpen();
    return &waiting;
  }
  char err[512] = "";
  FrameSource* source = openSource(opt.source, opt.seed, opt.frames, err, sizeof err,
                                   opt.skipBadFrames, opt.gtPath, groundTruthOptional(opt));
  if (!source) reporter.report(err);
  if (source && source->warning()[0] != '\0') reporter.report(source->warning());
  return source;
}

// A source that gave no frame: one line naming it, and whether its frames were damaged.
void reportNoFrame(const AppOptions& opt, const FrameSource& source, platform::Reporter& reporter) {
  char err[512];
  std::snprintf(err, sizeof err, "%.400s: no decodable frame%s",
                opt.source ? opt.source : source.name(),
                source.skippedFrames() > 0 ? " (every one damaged, skipped)" : " (it is empty)");
  reporter.report(err);
}

// Reads the source's first frame into the pipeline's slot, before the run, and hands the
// source on as one whose first frame is that slot (PrefetchedSource); kExitSource, said,
// when there is none.
int readFirstFrame(const AppOptions& opt, FrameSource*& source, FrameSlot& slot,
                   platform::Reporter& reporter) {
  const ReadStatus rs = source->next(slot);
  if (rs == ReadStatus::Error) {
    reporter.report(source->error());
    return kExitSource;
  }
  if (rs == ReadStatus::End) {
    reportNoFrame(opt, *source, reporter);
    return kExitSource;
  }
  static PrefetchedSource prefetched(*source);
  source = &prefetched;
  return kGoOn;
}

// When the target can only come from ground truth (no --box, --select, --snapshot), the
// first frame says whether the source has any. Without ground truth and without a link for
// a START, nothing could be tracked: exit 2 (a run that idles to its end and exits 0 would
// mislead). *groundTruth: the source has it (false when not looked at: a camera waited for).
int checkGroundTruth(const AppOptions& opt, const char* groundTruthName, FrameSource*& source,
                     FrameSlot& slot, bool* groundTruth, platform::Reporter& reporter) {
  *groundTruth = false;
  if (opt.hasBox || opt.select || opt.snapshotPath || !opt.useGroundTruth || liveCamera(opt))
    return kGoOn;
  if (const int code = readFirstFrame(opt, source, slot, reporter); code != kGoOn) return code;
  *groundTruth = slot.hasGroundTruth;
  if (*groundTruth || userTargetPossible(opt)) return kGoOn;
  const char* name = opt.source ? opt.source : source->name();
  char err[1024] = "";
  const size_t n = std::strlen(groundTruthName);
  if (n > 4 && std::strcmp(groundTruthName + n - 4, ".txt") == 0) {
    std::snprintf(err, sizeof err,
                  "%.400s: nothing to track: no ground truth (%.400s not found); %s", name,
                  groundTruthName, kWaysToATarget);
  } else {
    std::snprintf(err, sizeof err, "%.400s: nothing to track: no ground truth; %s", name,
                  kWaysToATarget);
  }
  reporter.report(err);
  return kExitUsage;
}

// --select and --snapshot work on the first frame, read here into the pipeline's slot:
// --snapshot writes it and ends the run (exit 0), --select sets opt.box from the drag and
// hands the source on as one whose first frame is that slot. A signal while the picker is
// open stops the run there, cleanly (exit 0, one closing line).
int resolveStartBox(AppOptions& opt, FrameSource*& source, FrameSlot& slot, LiveView& view,
                    platform::Reporter& reporter) {
  if (!opt.select && !opt.snapshotPath) return kGoOn;
  if (const int code = readFirstFrame(opt, source, slot, reporter); code != kGoOn) return code;
  char err[512] = "";
  if (opt.snapshotPath) {
    if (!writeSnapshot(slot.frame(), opt.snapshotPath, err, sizeof err, slot.scale.xFactor(),
                       slot.scale.yFactor())) {
      reporter.report(err);
      return kExitOutput;
    }
    if (slot.scale.scaled()) {
      std::snprintf(err, sizeof err,
                    "wrote %s: frame %d, scaled from %dx%d to %dx%d px, grid labelled in the "
                    "source's px; read the target's box off it and run with --box X,Y,W,H",
                    opt.snapshotPath, slot.index, slot.scale.sourceWidthPx,
                    slot.scale.sourceHeightPx, slot.rgb.width(), slot.rgb.height());
    } else {
      std::snprintf(err, sizeof err,
                    "wrote %s: frame %d, %dx%d px, grid every %d px; read the target's box off "
                    "it and run with --box X,Y,W,H",
                    opt.snapshotPath, slot.index, slot.rgb.width(), slot.rgb.height(),
                    kSnapshotGridPx);
    }
    reporter.report(err);
    return kExitOk;
  }
  const PickResult picked =
      opt.show ? view.pick(slot.frame(), &platform::stopRequested, &opt.box, err, sizeof err)
               : pickBox(slot.frame(), &platform::stopRequested, &opt.box, err, sizeof err);
  if (picked == PickResult::Interrupted) {  // a signal: a clean stop, as in any run
    reporter.report("stopped after 0 frames (signal, while --select was open)");
    return kExitOk;
  }
  if (picked == PickResult::Cancelled) {
    reporter.report(err);
    return kExitUsage;
  }
  opt.box = slot.scale.toSource(opt.box);  // picked on the frame as shown; --box is the source's
  opt.hasBox = true;
  std::snprintf(err, sizeof err, "picked --box %g,%g,%g,%g (give it to later runs)", opt.box.x,
                opt.box.y, opt.box.w, opt.box.h);
  reporter.report(err);
  return kGoOn;
}

// The CSV file, the serial port, the UDP socket and the video, opened before the first
// frame (exit 1 when one cannot be).
int openOutputs(const AppOptions& opt, const FrameSource& source, Outputs& out,
                platform::Reporter& reporter) {
  char err[512] = "";
  if (opt.outPath && !out.fileSink.openFile(opt.outPath, platform::TextFormat::Csv)) {
    reporter.report(out.fileSink.error());
    return kExitOutput;
  }
  if (opt.serialPath && !out.port.open(opt.serialPath, opt.baud)) {
    reporter.report(out.port.error());
    return kExitOutput;
  }
  if (opt.serialPath && out.port.notice()[0] != '\0') reporter.report(out.port.notice());
  if (opt.mavlinkUdp && !out.udp.open(opt.mavlinkUdp)) {
    reporter.report(out.udp.error());
    return kExitOutput;
  }
  if (opt.mavlinkUdp && !out.udp.countsDrops()) {  // said once: rx-errors cannot show them
    std::snprintf(err, sizeof err,
                  "%s: this system does not report the datagrams it drops (SO_RXQ_OVFL); "
                  "rx-errors will not count them",
                  out.udp.name());
    reporter.report(err);
  }
  out.videoOk = opt.videoPath != nullptr;
  if (opt.videoPath && !out.video.open(opt.videoPath, source.nominalFps(), err, sizeof err)) {
    reporter.report(err);
    return kExitOutput;
  }
  return kGoOn;
}

PipelineOptions pipelineOptions(const AppOptions& opt, const FrameSource& source,
                                const char* groundTruthName) {
  PipelineOptions po;
  po.maxFrames = opt.frames;
  po.hasBox = opt.hasBox;
  po.box = opt.box;
  po.useGroundTruth = opt.useGroundTruth;
  po.statusPeriodUs = opt.quiet ? 0 : 1000000;
  po.droppedFrames = droppedFrames;
  po.sourceName = opt.source ? opt.source : source.name();
  po.groundTruthName = groundTruthName;
  po.warnPoorTarget = true;
  po.sayScaling = !opt.quiet;
  po.linkName = linkName(opt);
  return po;
}

// The link the tracks go out on and the commands come in by: MAVLink (serial or UDP),
// our serial protocol, or none.
platform::TrackLink* makeLink(const AppOptions& opt, const uint8_t (&key)[32], Outputs& out,
                              const Clock& clock, platform::Reporter& reporter) {
  if (opt.protocol == Protocol::Mavlink) {
    platform::mavlink::LinkConfig mc;
    mc.sysId = static_cast<uint8_t>(opt.mavSysId);
    mc.compId = static_cast<uint8_t>(opt.mavCompId);
    mc.mount.rollDeg = opt.mountDeg[0];
    mc.mount.pitchDeg = opt.mountDeg[1];
    mc.mount.yawDeg = opt.mountDeg[2];
    for (int i = 0; i < 3; ++i) mc.mount.offsetM[i] = opt.mountOffsetM[i];
    mc.landingPosition = opt.landingPosition;
    // The link's output rate: a serial line's own (10 bits a byte), else UDP's default.
    if (opt.mavlinkRateBytesPerS > 0)
      mc.outputBytesPerS = static_cast<uint32_t>(opt.mavlinkRateBytesPerS);
    else if (!opt.mavlinkUdp)
      mc.outputBytesPerS = static_cast<uint32_t>(opt.baud / 10);
    if (opt.mavlinkKey) {  // read before the run: errors said at once
      mc.signing = true;
      mc.signingTimestamp = platform::signingTimestampNow();
    }
    std::memcpy(mc.key.bytes, key, sizeof mc.key.bytes);
    mc.acceptSysIdCount = opt.acceptSysIdCount;
    for (int i = 0; i < opt.acceptSysIdCount; ++i)
      mc.acceptSysIds[i] = static_cast<uint8_t>(opt.acceptSysIds[i]);
    platform::ByteStream& stream =
        opt.mavlinkUdp ? static_cast<platform::ByteStream&>(out.udp) : out.port;
    static platform::mavlink::MavlinkLink mavlinkLink(stream, clock, reporter, mc);
    return &mavlinkLink;
  }
  if (opt.serialPath) {
    static SerialLink serialLink(out.port, clock, reporter);
    return &serialLink;
  }
  return nullptr;
}

// The sinks and the link on the pipeline.
void attachOutputs(const AppOptions& opt, const uint8_t (&key)[32], Pipeline& pipeline,
                   Outputs& out, const Clock& clock, platform::Reporter& reporter) {
  if (opt.outPath) pipeline.addSink(&out.fileSink);
  // One line per frame floods a terminal: there, only with --stdout (pipes get them).
  const bool defaultOutput = !opt.outPath && !opt.serialPath && !opt.mavlinkUdp;
  out.stdoutIsTerminal = isatty(STDOUT_FILENO) == 1;
  if (opt.forceStdout || (defaultOutput && !out.stdoutIsTerminal)) {
    out.stdoutSink.attachStdout(platform::TextFormat::Line);
    pipeline.addSink(&out.stdoutSink);
  }
  out.link = makeLink(opt, key, out, clock, reporter);
  if (out.link) pipeline.attachLink(out.link);
}

// The frames, one pipeline step at a time, until the source ends, a STOP, a signal or the
// window's q; each tracked frame also goes to the summary, the video and the window.
RunEnd runLoop(const AppOptions& opt, Pipeline& pipeline, const FrameSlot& slot, LiveView& view,
               Outputs& out, RunSummary& summary, const Clock& clock,
               platform::Reporter& reporter) {
  char err[512] = "";
  RunEnd end;
  const uint64_t runStartUs = clock.nowUs();
  StepResult& r = end.result;
  while (r == StepResult::Continue && !platform::stopRequested()) {
    const uint32_t before = pipeline.frames();
    r = pipeline.step();
    if (pipeline.frames() == before) continue;    // no frame this step
    const ctp_track_t& t = pipeline.lastTrack();  // in the source's pixels, as sent out
    const Box truth = slot.scale.toSource(slot.groundTruth);
    // --no-gt: the ground truth is not scored either (no overlap figure at the end).
    summary.add(t, opt.useGroundTruth && slot.hasGroundTruth ? &truth : nullptr);
    if (!opt.show && !out.videoOk) continue;
    ViewTrack vt;
    vt.frameIndex = static_cast<uint32_t>(slot.index);
    vt.state = t.state;
    vt.flags = t.flags;
    // Drawn on the frame as the tracker saw it (scaled down when the source is larger).
    vt.box =
        slot.scale.toSlot(Box{static_cast<float>(t.box_px[0]), static_cast<float>(t.box_px[1]),
                              static_cast<float>(t.box_px[2]), static_cast<float>(t.box_px[3])});
    vt.confidence = static_cast<float>(t.confidence) / 65535.f;
    if (out.videoOk && !out.video.write(slot.frame(), vt, err, sizeof err)) {
      // Like any output: said once, tracking goes on, the exit code tells.
      reporter.report(err);
      out.videoOk = false;
    }
    if (!opt.show) continue;
    view.push(slot.frame(), vt);
    view.waitWhilePaused(&platform::stopRequested);
    Box picked{};
    if (view.takeReselect(&picked)) {  // on the next frame, as a serial START would be
      platform::StartRequest start;
      start.kind = platform::StartRequest::Kind::BoxPx;
      start.box = slot.scale.toSource(picked);  // a START's pixels are the source's
      pipeline.requestStart(start);
      std::snprintf(err, sizeof err, "re-selected --box %g,%g,%g,%g", start.box.x, start.box.y,
                    start.box.w, start.box.h);
      reporter.report(err);
    }
    if (view.quitRequested()) {
      end.windowQuit = true;
      break;
    }
  }
  end.runUs = clock.nowUs() - runStartUs;
  return end;
}

// The video read back, the CSV flushed, the link's last messages sent. False when the
// CSV could not be closed (its rows may sit in the page cache until here).
bool closeOutputs(const AppOptions& opt, Outputs& out, platform::Reporter& reporter) {
  char err[512] = "";
  if (opt.videoPath && out.videoOk) {
    if (out.video.close(err, sizeof err)) {
      std::snprintf(err, sizeof err, "wrote %s: %u frames", opt.videoPath,
                    static_cast<unsigned>(out.video.frames()));
    } else {
      out.videoOk = false;
    }
    reporter.report(err);
  }
  bool closed = true;
  if (opt.outPath && !out.fileSink.close()) {
    reporter.report(out.fileSink.error());
    closed = false;
  }
  if (out.link && !out.link->drain(1000)) {
    std::snprintf(err, sizeof err, "%s: could not send the last messages within 1 s",
                  linkName(opt));
    reporter.report(err);
  }
  return closed;
}

// A source that ended before its first frame gave nothing to track: not a success. True
// (and said) then.
bool reportEmptySource(const AppOptions& opt, const FrameSource& source, const Pipeline& pipeline,
                       const RunEnd& end, platform::Reporter& reporter) {
  if (end.result != StepResult::Done || pipeline.frames() != 0 || platform::stopRequested())
    return false;
  reportNoFrame(opt, source, reporter);
  return true;
}

// The exit code of a run that had frames: a source or box failure first, then any output.
int exitCode(const RunEnd& end, bool outputFailed) {
  switch (end.result) {
    case StepResult::SourceError:
      return kExitSource;
    case StepResult::BoxRejected:
      return kExitBoxRejected;
    default:
      return outputFailed ? kExitOutput : kExitOk;
  }
}

}  // namespace

int runCuetrack(int argc, char** argv, TrackerPort& tracker) {
  // First: a stop at any moment (while the command line, the key or the source is read)
  // ends the run with its summary and exit 0, as --help says.
  platform::installStopSignals();
  platform::StderrReporter reporter("cuetrack");
  AppOptions opt;
  static uint8_t mavlinkKey[32];
  if (const int code = checkCommandLine(argc, argv, opt, mavlinkKey, reporter); code != kGoOn)
    return code;

  static platform::MonotonicClock clock;
  if (!tracker.configure(opt.preset, opt.seed, &clock)) {
    char err[512];
    std::snprintf(err, sizeof err, "--config %s: unknown preset (best, dcf, 1.1-1.4, 2.1-2.5)",
                  opt.preset);
    reporter.report(err);
    return kExitUsage;
  }

  static platform::MonotonicSleeper sleeper;
  FrameSource* source = openFrameSource(opt, clock, sleeper, reporter);
  if (!source) return kExitSource;
  static FrameSlot slot;  // ~1.5 MiB
  static char groundTruthName[512];
  describeGroundTruth(opt.source, groundTruthName, sizeof groundTruthName, opt.gtPath);
  bool groundTruth = false;
  if (const int code = checkGroundTruth(opt, groundTruthName, source, slot, &groundTruth, reporter);
      code != kGoOn)
    return code;
  static LiveView view;
  char err[512] = "";
  if (opt.show && !view.start(&platform::stopRequested, err, sizeof err)) {
    reporter.report(err);
    return kExitUsage;
  }
  // From here an early end closes the window's thread first: Qt must not be torn down
  // under it at exit.
  if (const int code = resolveStartBox(opt, source, slot, view, reporter); code != kGoOn) {
    view.close();
    return code;
  }
  static PacedSource paced(*source, clock, sleeper, &platform::stopRequested);
  if (opt.realtime) source = &paced;  // a live Kinect is paced by its own clock anyway

  static Outputs out;
  if (const int code = openOutputs(opt, *source, out, reporter); code != kGoOn) {
    view.close();
    return code;
  }
  Pipeline pipeline(*source, slot, tracker, clock, reporter,
                    pipelineOptions(opt, *source, groundTruthName));
  attachOutputs(opt, mavlinkKey, pipeline, out, clock, reporter);
  if (!opt.quiet) printBanner(opt, groundTruthName, groundTruth, out.stdoutIsTerminal, reporter);

  RunSummary summary;
  const RunEnd end = runLoop(opt, pipeline, slot, view, out, summary, clock, reporter);
  pipeline.finish();
  const bool empty = reportEmptySource(opt, *source, pipeline, end, reporter);
  view.close();
  const bool closed = closeOutputs(opt, out, reporter);
  const int code =
      empty ? kExitSource
            : exitCode(end, pipeline.outputFailed() || !closed || (opt.videoPath && !out.videoOk));
  printSummary(opt, argv[0], pipeline, *source, out.link, summary, end, view.droppedFrames(),
               code != kExitOk, reporter);
  return code;
}

}  // namespace cuetrack::app
