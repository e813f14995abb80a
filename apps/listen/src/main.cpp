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

// One listening session: the port, the outputs and the loop, each a step.
class Session {
 public:
  Session(const listen::ListenOptions& opt, platform::SerialPort& port,
          platform::StderrReporter& problems)
      : _opt(opt), _port(port), _problems(problems) {}

  // The port, waited for when it is not there yet: false after its line.
  bool openPort();
  // --csv or stdout: false after its line.
  bool openTracks();
  // The loop, until a stop, --tracks, the idle timeout or a failure; what main returns,
  // after the summary line.
  int run();
  // Stopped while waiting for the port: the summary line (nothing received), exit 0.
  bool interrupted() const { return platform::stopRequested(); }
  int summaryOnly();

 private:
  bool resume(listen::Listener& listener);
  bool saveState(const listen::Listener& listener);
  bool waitForReturn(listen::Listener& listener);
  bool sendCommands(listen::Listener& listener);
  // One poll: false when the loop ends (why and _code set).
  bool step(listen::Listener& listener, platform::LineReporter& messages);
  void summary(const listen::Listener& listener);

  const listen::ListenOptions& _opt;
  platform::SerialPort& _port;
  platform::StderrReporter& _problems;
  platform::FdTrackSink _tracks;
  platform::MonotonicClock _clock;
  char _err[768] = "";
  uint64_t _lastRxUs = 0, _stateWrittenUs = 0;
  uint32_t _stateSeq = 0;
  bool _sent = false;
  int _code = 0;
  const char* _why = "interrupted";
};

bool Session::openPort() {
  const uint64_t startUs = _clock.nowUs();
  const bool waited = waitForPort(_opt.portPath, _opt.waitPortS, _problems);
  if (platform::stopRequested()) return false;  // the caller ends with the summary
  if (!_port.open(_opt.portPath, static_cast<int>(_opt.baud))) {
    if (waited) {
      const double waitedS = static_cast<double>(_clock.nowUs() - startUs) / 1e6;
      std::snprintf(_err, sizeof _err, "%s (waited %.0f s for it; --wait-port SECONDS)",
                    _port.error(), waitedS);
      _problems.report(_err);
    } else {
      _problems.report(_port.error());
    }
    return false;
  }
  if (_port.notice()[0] != '\0') _problems.report(_port.notice());  // a stale lock replaced
  std::snprintf(_err, sizeof _err, "%s: listening at %ld baud", _opt.portPath, _opt.baud);
  _problems.report(_err);
  return true;
}

bool Session::openTracks() {
  if (!_opt.csvPath) {
    _tracks.attachStdout(platform::TextFormat::Line);
    return true;
  }
  if (_tracks.openFile(_opt.csvPath, platform::TextFormat::Csv)) return true;
  _problems.report(_tracks.error());
  return false;
}

// --state: go on after the last run's seq.
bool Session::resume(listen::Listener& listener) {
  uint32_t savedSeq = 0;
  _err[0] = '\0';
  if (_opt.statePath && readState(_opt.statePath, &savedSeq, _err, sizeof _err)) {
    listener.resumeAfter(savedSeq);
    std::snprintf(_err, sizeof _err, "%s: the last run ended after seq %u", _opt.statePath,
                  savedSeq);
    _problems.report(_err);
  } else if (_opt.statePath && _err[0]) {
    _problems.report(_err);  // a damaged state file: say so, start afresh
  }
  _stateSeq = savedSeq;
  return true;
}

bool Session::saveState(const listen::Listener& listener) {
  const listen::SeqCounter& q = listener.seq();
  if (!_opt.statePath || !q.any() || (q.last() == _stateSeq && _stateWrittenUs != 0)) return true;
  _stateSeq = q.last();
  _stateWrittenUs = _clock.nowUs();
  return writeState(_opt.statePath, _stateSeq, _err, sizeof _err);
}

// --reconnect: the port went away; waits for it. False when stopped while waiting.
bool Session::waitForReturn(listen::Listener& listener) {
  std::snprintf(_err, sizeof _err, "%s: the port went away (%s); waiting for it", _opt.portPath,
                _port.error());
  _problems.report(_err);
  _port.close();
  uint64_t triedUs = 0;
  while (!platform::stopRequested() && !_port.isOpen()) {
    const uint64_t now = _clock.nowUs();
    if (triedUs == 0 || now - triedUs >= kReopenPeriodUs) {
      triedUs = now;
      if (_port.open(_opt.portPath, static_cast<int>(_opt.baud))) break;
    }
    usleep(50000);  // a slice of the wait, not a synchronisation
  }
  if (!_port.isOpen()) return false;  // interrupted while waiting
  std::snprintf(_err, sizeof _err, "%s: the port is back", _opt.portPath);
  _problems.report(_err);
  listener.noteReconnect();
  _lastRxUs = _clock.nowUs();
  return true;
}

// The --send commands, once the device is up and reading (it flushes its input when it
// opens the port). False after its line when one cannot be sent.
bool Session::sendCommands(listen::Listener& listener) {
  const listen::ListenStats& st = listener.stats();
  if (_sent || st.tracks + st.heartbeats + st.acks + st.errors == 0) return true;
  _sent = true;
  for (int i = 0; i < _opt.numSends; ++i) {
    if (!listener.send(_opt.commands[i])) {
      std::snprintf(_err, sizeof _err, "%s: cannot send '%s': %s", _opt.portPath, _opt.sends[i],
                    _port.error());
      _problems.report(_err);
      return false;
    }
  }
  return true;
}

bool Session::step(listen::Listener& listener, platform::LineReporter& messages) {
  bool received = false;
  const listen::PollResult r = listener.poll(100, &received);
  if (r == listen::PollResult::Closed && !_opt.reconnect) {
    std::snprintf(_err, sizeof _err, "%s: the port went away (%s); --reconnect waits for it",
                  _opt.portPath, _port.error());
    _problems.report(_err);
    _why = "port went away";
    _code = kExitPort;
    return false;
  }
  if (r == listen::PollResult::Closed) return waitForReturn(listener);
  if (r == listen::PollResult::OutputFailed || messages.failed()) {
    const bool csv = _opt.csvPath != nullptr;
    _why = messages.failed()
               ? (csv ? "message (stderr) write failed" : "message (stdout) write failed")
           : csv ? "CSV write failed"
                 : "track output (stdout) write failed";
    _code = kExitOutput;
    return false;
  }
  if (received) _lastRxUs = _clock.nowUs();
  if (_clock.nowUs() - _stateWrittenUs >= kStatePeriodUs && !saveState(listener)) {
    _problems.report(_err);
    _why = "state file write failed";
    _code = kExitOutput;
    return false;
  }
  if (!sendCommands(listener)) {
    _why = "a --send failed";
    _code = kExitPort;
    return false;
  }
  if (_opt.maxTracks >= 0 && listener.stats().tracks >= static_cast<uint32_t>(_opt.maxTracks)) {
    _why = "--tracks reached";
    return false;
  }
  if (_opt.idleS > 0 && _clock.nowUs() - _lastRxUs > static_cast<uint64_t>(_opt.idleS) * 1000000u) {
    _why = "idle timeout";
    _code = kExitIdle;
    return false;
  }
  return true;
}

void Session::summary(const listen::Listener& listener) {
  const listen::ListenStats& s = listener.stats();
  const ctp_stats_t& d = listener.decoderStats();
  const listen::SeqCounter& q = listener.seq();
  int n = std::snprintf(
      _err, sizeof _err,
      "%s: %u tracks, %u heartbeats, %u acks, %u errors; rejected %u (crc %u, framing %u, "
      "overlong %u, version %u); seq gaps %u",
      _why, s.tracks, s.heartbeats, s.acks, s.errors, s.rejected, d.crc, d.framing, d.overlong,
      d.version, s.seqGaps);
  if (q.any() && n > 0 && static_cast<size_t>(n) < sizeof _err)
    n += std::snprintf(_err + n, sizeof _err - static_cast<size_t>(n),
                       " (seq first %u last %u, device restarts %u)", q.first(), q.last(),
                       q.restarts());
  _problems.report(_err);
}

int Session::summaryOnly() {
  static platform::FdTrackSink none;
  platform::LineReporter messages(platform::StdStream::Err);
  listen::Listener listener(_port, none, messages, _problems);
  summary(listener);
  return 0;
}

int Session::run() {
  // With --csv, stdout may carry the CSV itself: other messages go to stderr.
  platform::LineReporter messages(_opt.csvPath ? platform::StdStream::Err
                                               : platform::StdStream::Out);
  listen::Listener listener(_port, _tracks, messages, _problems);
  resume(listener);
  _lastRxUs = _clock.nowUs();
  _sent = _opt.numSends == 0;
  while (!platform::stopRequested() && step(listener, messages)) {
  }
  _stateWrittenUs = 0;  // the last seq, whatever the period
  if (!saveState(listener)) {
    _problems.report(_err);
    if (_code == 0) _code = kExitOutput;
  }
  summary(listener);
  return _code;
}

}  // namespace

int main(int argc, char** argv) {
  platform::installStopSignals();  // first: a stop at any moment ends with the summary, exit 0
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
  static platform::SerialPort port;
  static Session session(opt, port, problems);
  if (!session.openPort()) return session.interrupted() ? session.summaryOnly() : kExitPort;
  if (!session.openTracks()) return kExitOutput;
  return session.run();
}
