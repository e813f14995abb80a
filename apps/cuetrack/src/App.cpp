#include "App.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "Options.hpp"
#include "OutputCheck.hpp"
#include "PacedSource.hpp"
#include "Pipeline.hpp"
#include "PrefetchedSource.hpp"
#include "RunSummary.hpp"
#include "SerialLink.hpp"
#include "Sources.hpp"
#include "View.hpp"
#include "WaitingSource.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
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

// Where the target comes from, for the banner.
void describeTarget(const AppOptions& opt, const char* groundTruthName, char* out, size_t n) {
  const bool live = opt.source && std::strncmp(opt.source, "kinect", 6) == 0;
  const char* orStart = opt.serialPath || opt.mavlinkUdp ? ", or a START on the link" : "";
  if (opt.select) {
    std::snprintf(out, n, "the box dragged with --select");
  } else if (opt.hasBox) {
    std::snprintf(out, n, "--box %g,%g,%g,%g", opt.box.x, opt.box.y, opt.box.w, opt.box.h);
  } else if (opt.useGroundTruth && !live) {
    std::snprintf(out, n, "ground truth (%.400s) where the target first shows%s", groundTruthName,
                  orStart);
  } else if (opt.serialPath || opt.mavlinkUdp) {
    std::snprintf(out, n, "waiting for a START on the link (or give --box / --select)");
  } else {
    std::snprintf(out, n, "none: nothing will be tracked (give --box X,Y,W,H or --select)");
  }
}

}  // namespace

int runCuetrack(int argc, char** argv, TrackerPort& tracker) {
  platform::StderrReporter reporter("cuetrack");
  char err[512] = "";
  AppOptions opt;
  switch (parseOptions(argc, argv, &opt, err, sizeof err)) {
    case ParseResult::Help:
      std::fputs(usageText().c_str(), stdout);
      return platform::stdoutWritten("cuetrack") ? kExitOk : kExitOutput;
    case ParseResult::Error:
      reporter.report(err);
      return kExitUsage;
    case ParseResult::Run:
      break;
  }
  // The signing key, before anything runs: a key others can read is refused (exit 2).
  static uint8_t mavlinkKey[32];
  if (opt.mavlinkKey &&
      !platform::readKeyFile(opt.mavlinkKey, mavlinkKey, sizeof mavlinkKey, err, sizeof err)) {
    std::snprintf(err + std::strlen(err), sizeof err - std::strlen(err), " (--mavlink-key)");
    reporter.report(err);
    return kExitUsage;
  }
  // Before anything opens: opening an output truncates it, and a reader may have it open.
  if (!checkOutputs(opt, err, sizeof err)) {
    reporter.report(err);
    return kExitUsage;
  }
  // Refused even without --serial: a typo here would otherwise surface only on the
  // day the port is added.
  if (!platform::SerialPort::baudSupported(opt.baud)) {
    std::snprintf(err, sizeof err, "--baud %d: unsupported (9600..921600, see --help)", opt.baud);
    reporter.report(err);
    return kExitUsage;
  }
  if ((opt.snapshotPath || opt.videoPath) && !viewBuilt()) {  // said before any frame is read
    char why[256];
    displayAvailable(why, sizeof why);  // the stub's "not built with OpenCV" line
    std::snprintf(err, sizeof err, "%s: %s", opt.snapshotPath ? "--snapshot" : "--video", why);
    reporter.report(err);
    return kExitUsage;
  }
  if (opt.show || opt.select) {
    char why[256];
    if (!displayAvailable(why, sizeof why)) {
      std::snprintf(err, sizeof err, "%s: %s", opt.show ? "--show" : "--select", why);
      reporter.report(err);
      return kExitUsage;
    }
  }
  if (opt.waitCamera && !kinectSupported()) {  // it would wait for ever
    reporter.report("--wait-camera: this build has no Kinect driver (libfreenect missing)");
    return kExitUsage;
  }
  platform::installStopSignals();

  static platform::MonotonicClock clock;
  if (!tracker.configure(opt.preset, opt.seed, &clock)) {
    std::snprintf(err, sizeof err, "--config %s: unknown preset (best, 1.1-1.4, 2.1-2.5)",
                  opt.preset);
    reporter.report(err);
    return kExitUsage;
  }

  static platform::MonotonicSleeper sleeper;
  FrameSource* source = nullptr;
  if (opt.waitCamera) {
    // The camera may come later: the run starts without it (outputs open, the serial
    // link served), and next() looks for it every second.
    static WaitingSource waiting(
        [](void* ctx, char* e, size_t n) {
          const AppOptions& o = *static_cast<const AppOptions*>(ctx);
          return openSource(o.source, o.seed, o.frames, e, n, o.skipBadFrames);
        },
        &opt, clock, sleeper, reporter, &platform::stopRequested);
    waiting.tryOpen();
    source = &waiting;
  } else {
    source = openSource(opt.source, opt.seed, opt.frames, err, sizeof err, opt.skipBadFrames);
    if (!source) {
      reporter.report(err);
      return kExitSource;
    }
  }
  static FrameSlot slot;  // ~1.5 MiB
  static LiveView view;
  if (opt.show && !view.start(err, sizeof err)) {
    reporter.report(err);
    return kExitUsage;
  }
  if (opt.select || opt.snapshotPath) {
    // The first frame, read into the pipeline's slot: the pipeline then starts on it.
    const ReadStatus rs = source->next(slot);
    if (rs != ReadStatus::Ok) {
      if (rs == ReadStatus::Error) {
        reporter.report(source->error());
      } else {
        std::snprintf(err, sizeof err, "%s: no frame to %s (the source is empty)",
                      opt.source ? opt.source : source->name(),
                      opt.select ? "select on" : "snapshot");
        reporter.report(err);
      }
      return kExitSource;
    }
    if (opt.snapshotPath) {
      if (!writeSnapshot(slot.frame(), opt.snapshotPath, err, sizeof err)) {
        reporter.report(err);
        return kExitOutput;
      }
      std::snprintf(err, sizeof err,
                    "wrote %s: frame %d, %dx%d px, grid every %d px; read the target's box off it "
                    "and run with --box X,Y,W,H",
                    opt.snapshotPath, slot.index, slot.rgb.width(), slot.rgb.height(),
                    kSnapshotGridPx);
      reporter.report(err);
      return kExitOk;
    }
    if (!(opt.show ? view.pick(slot.frame(), &opt.box, err, sizeof err)
                   : pickBox(slot.frame(), &opt.box, err, sizeof err))) {
      reporter.report(err);
      return kExitUsage;
    }
    opt.hasBox = true;
    std::snprintf(err, sizeof err, "picked --box %g,%g,%g,%g (give it to later runs)", opt.box.x,
                  opt.box.y, opt.box.w, opt.box.h);
    reporter.report(err);
    static PrefetchedSource prefetched(*source);
    source = &prefetched;
  }
  static PacedSource paced(*source, clock, sleeper, &platform::stopRequested);
  if (opt.realtime) source = &paced;  // a live Kinect is paced by its own clock anyway

  static platform::FdTrackSink fileSink;
  static platform::FdTrackSink stdoutSink;
  static platform::SerialPort port;
  if (opt.outPath && !fileSink.openFile(opt.outPath, platform::TextFormat::Csv)) {
    reporter.report(fileSink.error());
    return kExitOutput;
  }
  if (opt.serialPath && !port.open(opt.serialPath, opt.baud)) {
    reporter.report(port.error());
    return kExitOutput;
  }
  if (opt.serialPath && port.notice()[0] != '\0') reporter.report(port.notice());
  static platform::UdpSocket udp;
  if (opt.mavlinkUdp && !udp.open(opt.mavlinkUdp)) {
    reporter.report(udp.error());
    return kExitOutput;
  }
  if (opt.mavlinkUdp && !udp.countsDrops()) {  // said once: rx-errors cannot show them
    std::snprintf(err, sizeof err,
                  "%s: this system does not report the datagrams it drops (SO_RXQ_OVFL); "
                  "rx-errors will not count them",
                  udp.name());
    reporter.report(err);
  }

  static VideoOut video;
  bool videoOk = opt.videoPath != nullptr;
  if (opt.videoPath && !video.open(opt.videoPath, source->nominalFps(), err, sizeof err)) {
    reporter.report(err);
    return kExitOutput;
  }
  PipelineOptions po;
  po.maxFrames = opt.frames;
  po.hasBox = opt.hasBox;
  po.box = opt.box;
  po.useGroundTruth = opt.useGroundTruth;
  po.statusPeriodUs = opt.quiet ? 0 : 1000000;
  po.droppedFrames = droppedFrames;
  static char groundTruthName[512];
  describeGroundTruth(opt.source, groundTruthName, sizeof groundTruthName);
  po.sourceName = opt.source ? opt.source : source->name();
  po.groundTruthName = groundTruthName;
  po.warnPoorTarget = true;
  const char* linkName = opt.mavlinkUdp ? "udp" : "serial";  // as status and final lines say
  po.linkName = linkName;
  Pipeline pipeline(*source, slot, tracker, clock, reporter, po);
  if (opt.outPath) pipeline.addSink(&fileSink);
  // One line per frame floods a terminal: there, only with --stdout (pipes get them).
  const bool defaultOutput = !opt.outPath && !opt.serialPath && !opt.mavlinkUdp;
  const bool stdoutIsTerminal = isatty(STDOUT_FILENO) == 1;
  if (opt.forceStdout || (defaultOutput && !stdoutIsTerminal)) {
    stdoutSink.attachStdout(platform::TextFormat::Line);
    pipeline.addSink(&stdoutSink);
  }
  static platform::TrackLink* link = nullptr;
  if (opt.protocol == Protocol::Mavlink) {
    platform::mavlink::LinkConfig mc;
    mc.sysId = static_cast<uint8_t>(opt.mavSysId);
    mc.compId = static_cast<uint8_t>(opt.mavCompId);
    mc.mount.rollDeg = opt.mountDeg[0];
    mc.mount.pitchDeg = opt.mountDeg[1];
    mc.mount.yawDeg = opt.mountDeg[2];
    for (int i = 0; i < 3; ++i) mc.mount.offsetM[i] = opt.mountOffsetM[i];
    mc.landingPosition = opt.landingPosition;
    if (opt.mavlinkKey) {  // read before the run: errors said at once
      mc.signing = true;
      mc.signingTimestamp = platform::signingTimestampNow();
    }
    std::memcpy(mc.key.bytes, mavlinkKey, sizeof mc.key.bytes);
    mc.acceptSysIdCount = opt.acceptSysIdCount;
    for (int i = 0; i < opt.acceptSysIdCount; ++i)
      mc.acceptSysIds[i] = static_cast<uint8_t>(opt.acceptSysIds[i]);
    platform::ByteStream& stream = opt.mavlinkUdp ? static_cast<platform::ByteStream&>(udp) : port;
    static platform::mavlink::MavlinkLink mavlinkLink(stream, clock, reporter, mc);
    link = &mavlinkLink;
  } else if (opt.serialPath) {
    static SerialLink serialLink(port, clock, reporter);
    link = &serialLink;
  }
  if (link) pipeline.attachLink(link);

  if (!opt.quiet) {
    char sourceWhy[256], target[512], banner[1200];
    describeSourceChoice(opt.source, sourceWhy, sizeof sourceWhy);
    describeTarget(opt, groundTruthName, target, sizeof target);
    std::snprintf(
        banner, sizeof banner, "source %s | target: %s | config %s, seed %llu | output: %s%s",
        sourceWhy, target, opt.preset, static_cast<unsigned long long>(opt.seed),
        opt.serialPath                           ? opt.serialPath
        : opt.outPath                            ? opt.outPath
        : opt.mavlinkUdp                         ? opt.mavlinkUdp
        : (opt.forceStdout || !stdoutIsTerminal) ? "stdout, one line per frame"
                                                 : "the summary below (--stdout: a line per frame)",
        opt.show ? " | window: --show" : "");
    reporter.report(banner);
  }

  RunSummary summary;
  bool windowQuit = false;
  const uint64_t runStartUs = clock.nowUs();
  StepResult r = StepResult::Continue;
  while (r == StepResult::Continue && !platform::stopRequested()) {
    const uint32_t before = pipeline.frames();
    r = pipeline.step();
    if (pipeline.frames() == before) continue;  // no frame this step
    const ctp_track_t& t = pipeline.lastTrack();
    summary.add(t, slot.hasGroundTruth ? &slot.groundTruth : nullptr);
    if (!opt.show && !videoOk) continue;
    ViewTrack vt;
    vt.frameIndex = static_cast<uint32_t>(slot.index);
    vt.state = t.state;
    vt.box = Box{static_cast<float>(t.box_px[0]), static_cast<float>(t.box_px[1]),
                 static_cast<float>(t.box_px[2]), static_cast<float>(t.box_px[3])};
    vt.confidence = static_cast<float>(t.confidence) / 65535.f;
    if (videoOk && !video.write(slot.frame(), vt, err, sizeof err)) {
      // Like any output: said once, tracking goes on, the exit code tells.
      reporter.report(err);
      videoOk = false;
    }
    if (!opt.show) continue;
    view.push(slot.frame(), vt);
    view.waitWhilePaused(&platform::stopRequested);
    Box picked{};
    if (view.takeReselect(&picked)) {  // on the next frame, as a serial START would be
      platform::StartRequest start;
      start.kind = platform::StartRequest::Kind::BoxPx;
      start.box = picked;
      pipeline.requestStart(start);
      std::snprintf(err, sizeof err, "re-selected --box %g,%g,%g,%g", picked.x, picked.y, picked.w,
                    picked.h);
      reporter.report(err);
    }
    if (view.quitRequested()) {
      windowQuit = true;
      break;
    }
  }
  const uint64_t runUs = clock.nowUs() - runStartUs;
  pipeline.finish();
  // A source that ended before its first frame gave nothing to track: not a success.
  const bool empty = r == StepResult::Done && pipeline.frames() == 0 && !platform::stopRequested();
  if (empty) {
    std::snprintf(err, sizeof err, "%s: no decodable frame%s",
                  opt.source ? opt.source : source->name(),
                  source->skippedFrames() > 0 ? " (every one damaged, skipped)" : " (it is empty)");
    reporter.report(err);
  }
  view.close();
  if (opt.videoPath && videoOk) {
    if (video.close(err, sizeof err)) {
      std::snprintf(err, sizeof err, "wrote %s: %u frames", opt.videoPath,
                    static_cast<unsigned>(video.frames()));
    } else {
      videoOk = false;
    }
    reporter.report(err);
  }
  bool closeFailed = false;
  if (opt.outPath && !fileSink.close()) {  // the rows may sit in the page cache until here
    reporter.report(fileSink.error());
    closeFailed = true;
  }

  if (link && !link->drain(1000)) {
    std::snprintf(err, sizeof err, "%s: could not send the last messages within 1 s", linkName);
    reporter.report(err);
  }
  if (!opt.quiet) {
    int n = std::snprintf(err, sizeof err, "stopped after %u frames (%s)",
                          static_cast<unsigned>(pipeline.frames()),
                          platform::stopRequested()      ? "signal"
                          : windowQuit                   ? "window closed"
                          : r == StepResult::Stopped     ? "STOP command"
                          : r == StepResult::Done        ? "end of source or --frames"
                          : r == StepResult::OutputsGone ? "every output failed"
                                                         : "error");
    // Damaged frames skipped (--skip-bad-frames) never reached the tracker: say how many.
    if (source->skippedFrames() > 0 && n > 0 && static_cast<size_t>(n) < sizeof err)
      n += std::snprintf(err + n, sizeof err - static_cast<size_t>(n),
                         "; %d damaged frames skipped", source->skippedFrames());
    // What the link managed: a peer that stopped reading shows as tx-dropped.
    if (link && n > 0 && static_cast<size_t>(n) < sizeof err) {
      const platform::LinkStats& s = link->stats();
      std::snprintf(err + n, sizeof err - static_cast<size_t>(n),
                    "; %s sent %u tx-dropped %u rx %u rx-errors %u refused %u", linkName,
                    static_cast<unsigned>(s.sent), static_cast<unsigned>(s.txDropped),
                    static_cast<unsigned>(s.rxFrames), static_cast<unsigned>(s.rxErrors),
                    static_cast<unsigned>(s.rxRefused));
    }
    reporter.report(err);
    summary.format(runUs, err, sizeof err);
    if (opt.show) {
      const size_t used = std::strlen(err);
      std::snprintf(err + used, sizeof err - used, ", window dropped %llu of them",
                    static_cast<unsigned long long>(view.droppedFrames()));
    }
    reporter.report(err);
    std::snprintf(err, sizeof err,
                  "next: %s --show --realtime (watch it) | %s --select (pick your own target) | "
                  "docs/first-hour.md",
                  argv[0], argv[0]);
    reporter.report(err);
  } else {
    // Even --quiet: frames and messages are not lost without a word.
    if (source->skippedFrames() > 0) {
      std::snprintf(err, sizeof err, "%d damaged frames skipped", source->skippedFrames());
      reporter.report(err);
    }
    if (link && (link->stats().txDropped > 0 || link->stats().rxErrors > 0 ||
                 link->stats().rxRefused > 0)) {
      const platform::LinkStats& s = link->stats();
      std::snprintf(err, sizeof err, "%s sent %u tx-dropped %u rx %u rx-errors %u refused %u",
                    linkName, static_cast<unsigned>(s.sent), static_cast<unsigned>(s.txDropped),
                    static_cast<unsigned>(s.rxFrames), static_cast<unsigned>(s.rxErrors),
                    static_cast<unsigned>(s.rxRefused));
      reporter.report(err);
    }
  }
  if (empty) return kExitSource;
  switch (r) {
    case StepResult::SourceError:
      return kExitSource;
    case StepResult::BoxRejected:
      return kExitBoxRejected;
    default:
      return pipeline.outputFailed() || closeFailed || (opt.videoPath && !videoOk) ? kExitOutput
                                                                                   : kExitOk;
  }
}

}  // namespace cuetrack::app
