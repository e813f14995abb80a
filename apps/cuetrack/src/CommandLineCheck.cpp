#include "CommandLineCheck.hpp"

#include <cstdio>
#include <cstring>

#include "OutputCheck.hpp"
#include "Sources.hpp"
#include "View.hpp"
#include "cuetrack/drivers/SceneCatalogue.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/KeyFile.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"

namespace cuetrack::app {

bool userTargetPossible(const AppOptions& opt) {
  return opt.hasBox || opt.select || opt.serialPath || opt.mavlinkUdp;
}

bool liveCamera(const AppOptions& opt) {
  return opt.source && std::strncmp(opt.source, "kinect", 6) == 0;
}

// The command line and all that can be refused before anything opens (exit 2): a bad
// option, a readable signing key, an output that is also an input, a baud rate, a view or
// a camera this build lacks. Fills key with the MAVLink signing key when one is given.
int checkCommandLine(int argc, char** argv, AppOptions& opt, uint8_t (&key)[32],
                     platform::Reporter& reporter) {
  char err[512] = "";
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
  if (opt.mavlinkKey && !platform::readKeyFile(opt.mavlinkKey, key, sizeof key, err, sizeof err)) {
    std::snprintf(err + std::strlen(err), sizeof err - std::strlen(err), " (--mavlink-key)");
    reporter.report(err);
    return kExitUsage;
  }
  // An unknown scene is a bad command line, in every tool.
  if (!knownSceneSource(opt.source, err, sizeof err)) {
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
  // No way for a target to arrive: the run would stay idle to its end. A live camera has
  // no ground truth; --no-gt drops it. (A source without it is found on its first frame.)
  // --snapshot tracks nothing: it needs none.
  if (!userTargetPossible(opt) && !opt.snapshotPath) {
    const bool live = liveCamera(opt);
    if (!opt.useGroundTruth || live) {
      std::snprintf(err, sizeof err, "%s: nothing to track%s; %s", live ? opt.source : "--no-gt",
                    live ? " (a live camera has no ground truth)" : "", kWaysToATarget);
      reporter.report(err);
      return kExitUsage;
    }
  }
  return kGoOn;
}

}  // namespace cuetrack::app
