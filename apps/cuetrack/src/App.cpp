#include "App.hpp"

#include <cstdio>

#include "Options.hpp"
#include "PacedSource.hpp"
#include "Pipeline.hpp"
#include "SerialLink.hpp"
#include "Sources.hpp"
#include "WaitingSource.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/FdTrackSink.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#include "cuetrack/platform/linux/StderrReporter.hpp"
#include "cuetrack/platform/linux/UdpSocket.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"

namespace cuetrack::app {

int runCuetrack(int argc, char** argv, TrackerPort& tracker) {
  platform::StderrReporter reporter("cuetrack");
  char err[512] = "";
  AppOptions opt;
  switch (parseOptions(argc, argv, &opt, err, sizeof err)) {
    case ParseResult::Help:
      std::fputs(usageText(), stdout);
      return platform::stdoutWritten("cuetrack") ? kExitOk : kExitOutput;
    case ParseResult::Error:
      reporter.report(err);
      return kExitUsage;
    case ParseResult::Run:
      break;
  }
  // Refused even without --serial: a typo here would otherwise surface only on the
  // day the port is added.
  if (!platform::SerialPort::baudSupported(opt.baud)) {
    std::snprintf(err, sizeof err, "--baud %d: unsupported (9600..921600, see --help)", opt.baud);
    reporter.report(err);
    return kExitUsage;
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
  static platform::UdpSocket udp;
  if (opt.mavlinkUdp && !udp.open(opt.mavlinkUdp)) {
    reporter.report(udp.error());
    return kExitOutput;
  }

  static FrameSlot slot;  // ~1.5 MiB
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
  Pipeline pipeline(*source, slot, tracker, clock, reporter, po);
  if (opt.outPath) pipeline.addSink(&fileSink);
  if (opt.forceStdout || (!opt.outPath && !opt.serialPath && !opt.mavlinkUdp)) {
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
    platform::ByteStream& stream = opt.mavlinkUdp ? static_cast<platform::ByteStream&>(udp) : port;
    static platform::mavlink::MavlinkLink mavlinkLink(stream, clock, reporter, mc);
    link = &mavlinkLink;
  } else if (opt.serialPath) {
    static SerialLink serialLink(port, clock, reporter);
    link = &serialLink;
  }
  if (link) pipeline.attachLink(link);

  StepResult r = StepResult::Continue;
  while (r == StepResult::Continue && !platform::stopRequested()) r = pipeline.step();
  pipeline.finish();
  bool closeFailed = false;
  if (opt.outPath && !fileSink.close()) {  // the rows may sit in the page cache until here
    reporter.report(fileSink.error());
    closeFailed = true;
  }

  if (link && !link->drain(1000))
    reporter.report("serial: could not send the last messages within 1 s");
  if (!opt.quiet) {
    int n = std::snprintf(err, sizeof err, "stopped after %u frames (%s)",
                          static_cast<unsigned>(pipeline.frames()),
                          platform::stopRequested()      ? "signal"
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
                    "; serial sent %u tx-dropped %u rx-errors %u", static_cast<unsigned>(s.sent),
                    static_cast<unsigned>(s.txDropped), static_cast<unsigned>(s.rxErrors));
    }
    reporter.report(err);
  } else {
    // Even --quiet: frames and messages are not lost without a word.
    if (source->skippedFrames() > 0) {
      std::snprintf(err, sizeof err, "%d damaged frames skipped", source->skippedFrames());
      reporter.report(err);
    }
    if (link && link->stats().txDropped > 0) {
      const platform::LinkStats& s = link->stats();
      std::snprintf(err, sizeof err, "serial sent %u tx-dropped %u rx-errors %u",
                    static_cast<unsigned>(s.sent), static_cast<unsigned>(s.txDropped),
                    static_cast<unsigned>(s.rxErrors));
      reporter.report(err);
    }
  }
  switch (r) {
    case StepResult::SourceError:
      return kExitSource;
    case StepResult::BoxRejected:
      return kExitBoxRejected;
    default:
      return pipeline.outputFailed() || closeFailed ? kExitOutput : kExitOk;
  }
}

}  // namespace cuetrack::app
