// cuetrack-listen PORT [--baud N] [--csv FILE] [--send COMMAND]...
// Host tool: decodes the track stream of `cuetrack --serial`, prints or saves it,
// sends commands. Runs until interrupted or until the port closes.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "ListenOptions.hpp"
#include "Listener.hpp"
#include "cuetrack/platform/CommandText.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/FdTrackSink.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#include "cuetrack/platform/linux/StderrReporter.hpp"

namespace {

using namespace cuetrack;

constexpr int kExitPort = 1;
constexpr int kExitUsage = 2;
constexpr int kExitOutput = 3;
constexpr int kExitIdle = 4;
constexpr uint64_t kReopenPeriodUs = 500000;
constexpr uint64_t kStatePeriodUs = 1000000;

// A port path that does not exist yet, in a folder that does (a pty socat is about to
// link, a USB adapter being plugged in): wait up to waitS for it. True when it waited.
bool waitForPort(const char* path, long waitS, platform::Reporter& reporter) {
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
  platform::MonotonicClock clock;
  platform::MonotonicSleeper sleeper;
  const uint64_t endUs = clock.nowUs() + static_cast<uint64_t>(waitS) * 1000000u;
  while (access(path, F_OK) != 0 && clock.nowUs() < endUs && !platform::stopRequested()) {
    sleeper.sleepUs(50000);  // polling a path: inotify would not see a symlink's target
  }
  return true;
}

// --state FILE: "last_seq N". False when there is no such file (a first run).
bool readState(const char* path, uint32_t* lastSeq, char* err, size_t errLen) {
  FILE* f = std::fopen(path, "r");
  if (!f) return false;
  unsigned long v = 0;
  const bool ok = std::fscanf(f, "last_seq %lu", &v) == 1 && v <= 0xffffffffUL;
  std::fclose(f);
  if (!ok) std::snprintf(err, errLen, "%s: not a state file (expected 'last_seq N')", path);
  *lastSeq = static_cast<uint32_t>(v);
  return ok;
}

// Written whole or not at all: a temporary name, then rename.
bool writeState(const char* path, uint32_t lastSeq, char* err, size_t errLen) {
  char tmp[1024];
  std::snprintf(tmp, sizeof tmp, "%s.tmp", path);
  FILE* f = std::fopen(tmp, "w");
  bool ok = f && std::fprintf(f, "last_seq %u\n", lastSeq) > 0;
  if (f) ok = std::fclose(f) == 0 && ok;
  if (ok) ok = std::rename(tmp, path) == 0;
  if (!ok) {
    std::snprintf(err, errLen, "%s: cannot write the state file: %s", path, std::strerror(errno));
    std::remove(tmp);
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  platform::StderrReporter problems("cuetrack-listen");
  char err[768];
  static listen::ListenOptions opt;  // static: 32 parsed commands
  switch (listen::parseListenOptions(argc, argv, &opt, err, sizeof err)) {
    case listen::ListenParse::Help:
      std::fputs(listen::listenHelp().c_str(), stdout);
      return platform::stdoutWritten("cuetrack-listen") ? 0 : kExitOutput;
    case listen::ListenParse::Error:
      problems.report(err);
      return kExitUsage;
    case listen::ListenParse::Run:
      break;
  }
  const char* portPath = opt.portPath;
  const char* csvPath = opt.csvPath;
  const char* statePath = opt.statePath;
  const bool reconnect = opt.reconnect;
  const long baud = opt.baud, maxTracks = opt.maxTracks, idleS = opt.idleS;
  const char* const* sends = opt.sends;
  const ctp_command_t* commands = opt.commands;
  const int numSends = opt.numSends;

  platform::installStopSignals();
  static platform::SerialPort port;
  const bool waited = waitForPort(portPath, opt.waitPortS, problems);
  if (!port.open(portPath, static_cast<int>(baud))) {
    if (waited) {
      std::snprintf(err, sizeof err, "%s (waited %ld s for it; --wait-port SECONDS)", port.error(),
                    opt.waitPortS);
      problems.report(err);
    } else {
      problems.report(port.error());
    }
    return kExitPort;
  }
  if (port.notice()[0] != '\0') problems.report(port.notice());  // a stale lock replaced
  std::snprintf(err, sizeof err, "%s: listening at %ld baud", portPath, baud);
  problems.report(err);
  static platform::FdTrackSink tracks;
  if (csvPath) {
    if (!tracks.openFile(csvPath, platform::TextFormat::Csv)) {
      problems.report(tracks.error());
      return kExitOutput;
    }
  } else {
    tracks.attachStdout(platform::TextFormat::Line);
  }
  // With --csv, stdout may carry the CSV itself: other messages go to stderr.
  platform::LineReporter messages(csvPath ? platform::StdStream::Err : platform::StdStream::Out);
  listen::Listener listener(port, tracks, messages, problems);
  uint32_t savedSeq = 0;
  if (statePath && readState(statePath, &savedSeq, err, sizeof err)) {
    listener.resumeAfter(savedSeq);
    std::snprintf(err, sizeof err, "%s: the last run ended after seq %u", statePath, savedSeq);
    problems.report(err);
  } else if (statePath && err[0]) {
    problems.report(err);  // a damaged state file: say so, start afresh
  }

  platform::MonotonicClock clock;
  uint64_t lastRxUs = clock.nowUs(), stateWrittenUs = 0;
  uint32_t stateSeq = savedSeq;
  int code = 0;
  const char* why = "interrupted";
  bool sent = numSends == 0;
  auto saveState = [&]() {
    const listen::SeqCounter& q = listener.seq();
    if (!statePath || !q.any() || (q.last() == stateSeq && stateWrittenUs != 0)) return true;
    stateSeq = q.last();
    stateWrittenUs = clock.nowUs();
    return writeState(statePath, stateSeq, err, sizeof err);
  };
  while (!platform::stopRequested()) {
    bool received = false;
    const listen::PollResult r = listener.poll(100, &received);
    if (r == listen::PollResult::Closed && !reconnect) {
      std::snprintf(err, sizeof err, "%s: the port went away (%s); --reconnect waits for it",
                    portPath, port.error());
      problems.report(err);
      why = "port went away";
      code = kExitPort;
      break;
    }
    if (r == listen::PollResult::Closed) {
      std::snprintf(err, sizeof err, "%s: the port went away (%s); waiting for it", portPath,
                    port.error());
      problems.report(err);
      port.close();
      uint64_t triedUs = 0;
      while (!platform::stopRequested() && !port.isOpen()) {
        const uint64_t now = clock.nowUs();
        if (triedUs == 0 || now - triedUs >= kReopenPeriodUs) {
          triedUs = now;
          if (port.open(portPath, static_cast<int>(baud))) break;
        }
        usleep(50000);  // a slice of the wait, not a synchronisation
      }
      if (!port.isOpen()) break;  // interrupted while waiting
      std::snprintf(err, sizeof err, "%s: the port is back", portPath);
      problems.report(err);
      listener.noteReconnect();
      lastRxUs = clock.nowUs();
      continue;
    }
    if (r == listen::PollResult::OutputFailed || messages.failed()) {
      why = messages.failed()
                ? (csvPath ? "message (stderr) write failed" : "message (stdout) write failed")
            : csvPath ? "CSV write failed"
                      : "track output (stdout) write failed";
      code = kExitOutput;
      break;
    }
    if (received) lastRxUs = clock.nowUs();
    if (clock.nowUs() - stateWrittenUs >= kStatePeriodUs && !saveState()) {
      problems.report(err);
      why = "state file write failed";
      code = kExitOutput;
      break;
    }
    const listen::ListenStats& st = listener.stats();
    if (!sent && st.tracks + st.heartbeats + st.acks + st.errors > 0) {
      // The device is up and reading (it flushes its input when it opens the port).
      sent = true;
      for (int i = 0; i < numSends; ++i) {
        if (!listener.send(commands[i])) {
          std::snprintf(err, sizeof err, "%s: cannot send '%s': %s", portPath, sends[i],
                        port.error());
          problems.report(err);
          return kExitPort;
        }
      }
    }
    if (maxTracks >= 0 && listener.stats().tracks >= static_cast<uint32_t>(maxTracks)) {
      why = "--tracks reached";
      break;
    }
    if (idleS > 0 && clock.nowUs() - lastRxUs > static_cast<uint64_t>(idleS) * 1000000u) {
      why = "idle timeout";
      code = kExitIdle;
      break;
    }
  }
  stateWrittenUs = 0;  // the last seq, whatever the period
  if (!saveState()) {
    problems.report(err);
    if (code == 0) code = kExitOutput;
  }
  const listen::ListenStats& s = listener.stats();
  const ctp_stats_t& d = listener.decoderStats();
  const listen::SeqCounter& q = listener.seq();
  int n = std::snprintf(
      err, sizeof err,
      "%s: %u tracks, %u heartbeats, %u acks, %u errors; rejected %u (crc %u, framing %u, "
      "overlong %u, version %u); seq gaps %u",
      why, s.tracks, s.heartbeats, s.acks, s.errors, s.rejected, d.crc, d.framing, d.overlong,
      d.version, s.seqGaps);
  if (q.any() && n > 0 && static_cast<size_t>(n) < sizeof err)
    n += std::snprintf(err + n, sizeof err - static_cast<size_t>(n),
                       " (seq first %u last %u, device restarts %u)", q.first(), q.last(),
                       q.restarts());
  problems.report(err);
  return code;
}
