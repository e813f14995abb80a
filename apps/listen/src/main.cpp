// cuetrack-listen PORT [--baud N] [--csv FILE] [--send COMMAND]...
// Host tool: decodes the track stream of `cuetrack --serial`, prints or saves it,
// sends commands. Runs until interrupted or until the port closes.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "Listener.hpp"
#include "cuetrack/platform/CommandText.hpp"
#include "cuetrack/platform/linux/FdTrackSink.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#include "cuetrack/platform/linux/StderrReporter.hpp"

namespace {

using namespace cuetrack;

constexpr int kMaxSends = 32;

const char* kUsage =
    "usage: cuetrack-listen PORT [--baud N] [--csv FILE] [--send COMMAND]... [--tracks N]\n"
    "                       [--idle-timeout SECONDS] [--wait-port SECONDS]\n"
    "Decodes cuetrack's serial stream (docs/serial-protocol.md): one line per track on\n"
    "stdout, or with --csv a CSV file (header + one row per track; '-' = stdout). Other\n"
    "messages (ack, error, heartbeat) go to stdout, or to stderr with --csv.\n"
    "  --baud N             9600..921600 (default 115200)\n"
    "  --send COMMAND       start:X,Y,W,H  reset  stop  rate:HZ; sent in order as soon as\n"
    "                       the first message shows the device is up\n"
    "  --tracks N           exit after N track messages\n"
    "  --idle-timeout S     exit with code 4 when nothing arrives for S seconds\n"
    "  --wait-port S        PORT not there yet (a USB adapter being plugged in, a socat\n"
    "                       pty starting) in a folder that exists: wait up to S seconds\n"
    "                       for it (default 5, 0 = fail at once)\n"
    "exit codes: 0 interrupted, port closed or --tracks reached; 1 bad command line;\n"
    "  2 port cannot be opened or a command cannot be sent; 3 the CSV (or, without --csv,\n"
    "  stdout) write failed; 4 idle timeout\n";

bool parseInt(const char* s, long lo, long hi, long* out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || errno != 0 || v < lo || v > hi) return false;
  *out = v;
  return true;
}

// A port path that does not exist yet, in a folder that does (a pty socat is about to
// link, a USB adapter being plugged in): wait up to waitS for it. True when it waited.
bool waitForPort(const char* path, long waitS, const platform::MonotonicClock& clock,
                 platform::Reporter& reporter) {
  if (waitS <= 0 || access(path, F_OK) == 0) return false;
  char dir[512];
  std::snprintf(dir, sizeof dir, "%s", path);
  char* slash = std::strrchr(dir, '/');
  if (slash == dir) {
    dir[1] = '\0';
  } else if (slash) {
    *slash = '\0';
  } else {
    std::snprintf(dir, sizeof dir, ".");
  }
  if (access(dir, F_OK) != 0) return false;  // a typo in the folder: fail at once
  char line[600];
  std::snprintf(line, sizeof line, "%s: not there yet, waiting up to %ld s for it", path, waitS);
  reporter.report(line);
  platform::MonotonicSleeper sleeper;
  const uint64_t endUs = clock.nowUs() + static_cast<uint64_t>(waitS) * 1000000u;
  while (access(path, F_OK) != 0 && clock.nowUs() < endUs && !platform::stopRequested()) {
    sleeper.sleepUs(50000);  // polling a path: inotify would not see a symlink's target
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  platform::StderrReporter problems("cuetrack-listen");
  const char* portPath = nullptr;
  const char* csvPath = nullptr;
  long baud = 115200, maxTracks = -1, idleS = -1, waitPortS = 5;
  const char* sends[kMaxSends];
  int numSends = 0;
  char err[768];
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0) {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (std::strcmp(a, "--baud") == 0 && hasValue) {
      if (!parseInt(argv[++i], 1, 4000000, &baud) ||
          !platform::SerialPort::baudSupported(static_cast<int>(baud))) {
        std::snprintf(err, sizeof err, "--baud %s: unsupported (9600..921600)", argv[i]);
        problems.report(err);
        return 1;
      }
    } else if (std::strcmp(a, "--csv") == 0 && hasValue) {
      csvPath = argv[++i];
    } else if (std::strcmp(a, "--send") == 0 && hasValue) {
      if (numSends >= kMaxSends) {
        problems.report("too many --send (at most 32)");
        return 1;
      }
      sends[numSends++] = argv[++i];
    } else if (std::strcmp(a, "--tracks") == 0 && hasValue) {
      if (!parseInt(argv[++i], 0, 2000000000L, &maxTracks)) {
        std::snprintf(err, sizeof err, "--tracks %s: expected a count", argv[i]);
        problems.report(err);
        return 1;
      }
    } else if (std::strcmp(a, "--idle-timeout") == 0 && hasValue) {
      if (!parseInt(argv[++i], 1, 86400, &idleS)) {
        std::snprintf(err, sizeof err, "--idle-timeout %s: expected seconds >= 1", argv[i]);
        problems.report(err);
        return 1;
      }
    } else if (std::strcmp(a, "--wait-port") == 0 && hasValue) {
      if (!parseInt(argv[++i], 0, 86400, &waitPortS)) {
        std::snprintf(err, sizeof err, "--wait-port %s: expected seconds >= 0", argv[i]);
        problems.report(err);
        return 1;
      }
    } else if (a[0] == '-' && a[1] != '\0') {
      std::snprintf(err, sizeof err, "unknown option or missing value: '%s' (see --help)", a);
      problems.report(err);
      return 1;
    } else if (!portPath) {
      portPath = a;
    } else {
      std::snprintf(err, sizeof err, "unexpected argument '%s' (one PORT only)", a);
      problems.report(err);
      return 1;
    }
  }
  if (!portPath) {
    problems.report("missing PORT (see --help)");
    return 1;
  }
  // Validate every command before touching the port.
  ctp_command_t commands[kMaxSends];
  for (int i = 0; i < numSends; ++i) {
    if (!platform::parseCommandText(sends[i], static_cast<uint16_t>(i + 1), &commands[i], err,
                                    sizeof err)) {
      problems.report(err);
      return 1;
    }
  }

  platform::installStopSignals();
  static platform::SerialPort port;
  platform::MonotonicClock clock;
  const bool waited = waitForPort(portPath, waitPortS, clock, problems);
  if (!port.open(portPath, static_cast<int>(baud))) {
    if (waited) {
      std::snprintf(err, sizeof err, "%s (waited %ld s for it; --wait-port SECONDS)", port.error(),
                    waitPortS);
      problems.report(err);
    } else {
      problems.report(port.error());
    }
    return 2;
  }
  std::snprintf(err, sizeof err, "%s: listening at %ld baud", portPath, baud);
  problems.report(err);
  static platform::FdTrackSink tracks;
  if (csvPath) {
    if (!tracks.openFile(csvPath, platform::TextFormat::Csv)) {
      problems.report(tracks.error());
      return 3;
    }
  } else {
    tracks.attachStdout(platform::TextFormat::Line);
  }
  // With --csv, stdout may carry the CSV itself: other messages go to stderr.
  platform::LineReporter messages(csvPath ? platform::StdStream::Err : platform::StdStream::Out);
  listen::Listener listener(port, tracks, messages, problems);

  uint64_t lastRxUs = clock.nowUs();
  int code = 0;
  const char* why = "interrupted";
  bool sent = numSends == 0;
  while (!platform::stopRequested()) {
    bool received = false;
    const listen::PollResult r = listener.poll(100, &received);
    if (r == listen::PollResult::Closed) {
      why = "port closed";
      break;
    }
    if (r == listen::PollResult::OutputFailed) {
      why = csvPath ? "CSV write failed" : "track output (stdout) write failed";
      code = 3;
      break;
    }
    if (received) lastRxUs = clock.nowUs();
    const listen::ListenStats& st = listener.stats();
    if (!sent && st.tracks + st.heartbeats + st.acks + st.errors > 0) {
      // The device is up and reading (it flushes its input when it opens the port).
      sent = true;
      for (int i = 0; i < numSends; ++i) {
        if (!listener.send(commands[i])) {
          std::snprintf(err, sizeof err, "%s: cannot send '%s': %s", portPath, sends[i],
                        port.error());
          problems.report(err);
          return 2;
        }
      }
    }
    if (maxTracks >= 0 && listener.stats().tracks >= static_cast<uint32_t>(maxTracks)) {
      why = "--tracks reached";
      break;
    }
    if (idleS > 0 && clock.nowUs() - lastRxUs > static_cast<uint64_t>(idleS) * 1000000u) {
      why = "idle timeout";
      code = 4;
      break;
    }
  }
  const listen::ListenStats& s = listener.stats();
  const ctp_stats_t& d = listener.decoderStats();
  std::snprintf(
      err, sizeof err,
      "%s: %u tracks, %u heartbeats, %u acks, %u errors; rejected %u (crc %u, framing %u, "
      "overlong %u, version %u); seq gaps %u",
      why, s.tracks, s.heartbeats, s.acks, s.errors, s.rejected, d.crc, d.framing, d.overlong,
      d.version, s.seqGaps);
  problems.report(err);
  return code;
}
