#include "RunReport.hpp"

#include <cstdio>
#include <cstring>

#include "DocPath.hpp"
#include "Sources.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

namespace cuetrack::app {
namespace {

// Where the target comes from, for the banner.
void describeTarget(const AppOptions& opt, const char* groundTruthName, bool groundTruth, char* out,
                    size_t n) {
  const char* orStart = opt.serialPath || opt.mavlinkUdp ? ", or a START on the link" : "";
  if (opt.select) {
    std::snprintf(out, n, "the box dragged with --select");
  } else if (opt.hasBox) {
    std::snprintf(out, n, "--box %g,%g,%g,%g", opt.box.x, opt.box.y, opt.box.w, opt.box.h);
  } else if (opt.useGroundTruth && groundTruth) {
    std::snprintf(out, n, "ground truth (%.400s) where the target first shows%s", groundTruthName,
                  orStart);
  } else {  // App.cpp refused a run with no way to a target at all
    const size_t len = std::strlen(groundTruthName);
    const bool missingFile =
        opt.useGroundTruth && len > 4 && std::strcmp(groundTruthName + len - 4, ".txt") == 0;
    std::snprintf(out, n, "waiting for a START on the link (%s%.400s%sor give --box / --select)",
                  missingFile ? "no ground truth: " : "", missingFile ? groundTruthName : "",
                  missingFile ? " not found; " : "");
  }
}

// The link's counters at the end in one clause, e.g. "serial sent 10 tx-dropped 0 rx 2 ...":
// what is still queued then never reaches the peer, so it counts as dropped. MAVLink's
// discarded bytes are split by reason after rx-errors (docs/mavlink.md).
int formatLinkStats(const char* name, const platform::LinkStats& s, char* out, size_t n) {
  char why[96] = "";
  if (s.rxBadCrc + s.rxBadLength + s.rxBadUnknown > 0)
    std::snprintf(why, sizeof why, " (crc %u, length %u, unknown %u)",
                  static_cast<unsigned>(s.rxBadCrc), static_cast<unsigned>(s.rxBadLength),
                  static_cast<unsigned>(s.rxBadUnknown));
  return std::snprintf(out, n, "%s sent %u tx-dropped %u rx %u rx-errors %u%s refused %u", name,
                       static_cast<unsigned>(s.sent), static_cast<unsigned>(s.txDropped + s.queued),
                       static_cast<unsigned>(s.rxFrames), static_cast<unsigned>(s.rxErrors), why,
                       static_cast<unsigned>(s.rxRefused));
}

}  // namespace

const char* linkName(const AppOptions& opt) {
  return opt.mavlinkUdp ? "udp" : "serial";
}

void printBanner(const AppOptions& opt, const char* groundTruthName, bool groundTruth,
                 bool stdoutIsTerminal, platform::Reporter& reporter) {
  char sourceWhy[256], target[512], banner[1200];
  describeSourceChoice(opt.source, sourceWhy, sizeof sourceWhy);
  describeTarget(opt, groundTruthName, groundTruth, target, sizeof target);
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

void printSummary(const AppOptions& opt, const char* program, const Pipeline& pipeline,
                  const FrameSource& source, const platform::TrackLink* link,
                  const RunSummary& summary, const RunEnd& end, uint64_t windowDroppedFrames,
                  bool failed, platform::Reporter& reporter) {
  char err[512] = "";
  const char* name = linkName(opt);
  const StepResult r = end.result;
  if (opt.quiet) {
    // Losses: frames the target was given but not tracked (lost or hidden), frames skipped,
    // messages the link dropped.
    const uint32_t untracked = summary.frames() - summary.tracked() - summary.idle();
    if (untracked > 0) {
      std::snprintf(err, sizeof err, "target not tracked on %u of %u frames (lost or hidden)",
                    untracked, summary.frames() - summary.idle());
      reporter.report(err);
    }
    if (source.skippedFrames() > 0) {
      std::snprintf(err, sizeof err, "%d damaged frames skipped", source.skippedFrames());
      reporter.report(err);
    }
    if (link && (link->stats().txDropped + link->stats().queued > 0 || link->stats().rxErrors > 0 ||
                 link->stats().rxRefused > 0)) {
      formatLinkStats(name, link->stats(), err, sizeof err);
      reporter.report(err);
    }
    return;
  }
  int n = std::snprintf(err, sizeof err, "stopped after %u frames (%s)",
                        static_cast<unsigned>(pipeline.frames()),
                        platform::stopRequested()      ? "signal"
                        : end.windowQuit               ? "window closed"
                        : r == StepResult::Stopped     ? "STOP command"
                        : r == StepResult::Done        ? "end of source or --frames"
                        : r == StepResult::OutputsGone ? "every output failed"
                                                       : "error");
  // Damaged frames skipped (--skip-bad-frames) never reached the tracker: say how many.
  if (source.skippedFrames() > 0 && n > 0 && static_cast<size_t>(n) < sizeof err)
    n += std::snprintf(err + n, sizeof err - static_cast<size_t>(n), "; %d damaged frames skipped",
                       source.skippedFrames());
  // What the link managed: a peer that stopped reading shows as tx-dropped.
  if (link && n > 0 && static_cast<size_t>(n) < sizeof err) {
    n += std::snprintf(err + n, sizeof err - static_cast<size_t>(n), "; ");
    if (static_cast<size_t>(n) < sizeof err)
      formatLinkStats(name, link->stats(), err + n, sizeof err - static_cast<size_t>(n));
  }
  if (failed) {  // the error line said why; this says how far it got, if anywhere
    if (pipeline.frames() == 0) return;
    reporter.report(err);
    if (r != StepResult::SourceError) return;
    summary.format(end.runUs, err, sizeof err);  // what was tracked before it broke
    reporter.report(err);
    if (!opt.skipBadFrames && source.skippedFrames() == 0)
      reporter.report(
          "next: a recording damaged or cut short mid-way: --skip-bad-frames skips its bad "
          "frames (counted) and goes on to the end");
    return;
  }
  reporter.report(err);
  summary.format(end.runUs, err, sizeof err);
  if (opt.show) {
    const size_t used = std::strlen(err);
    std::snprintf(err + used, sizeof err - used, ", window dropped %llu of them",
                  static_cast<unsigned long long>(windowDroppedFrames));
  }
  reporter.report(err);
  std::snprintf(err, sizeof err,
                "next: %s --show --realtime (watch it) | %s --select (pick your own target) | "
                "%s",
                program, program, findDoc("docs/first-hour.md").c_str());
  reporter.report(err);
}

}  // namespace cuetrack::app
