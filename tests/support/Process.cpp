#include "Process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

extern char** environ;

namespace cuetrack::test {

void pauseMs(int ms) {
  timespec ts{ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&ts, nullptr);
}

bool fileExists(const char* path) {
  return ::access(path, F_OK) == 0;
}

bool readFile(const char* path, char* buf, size_t cap) {
  FILE* f = std::fopen(path, "rb");
  if (!f) return false;
  const size_t n = std::fread(buf, 1, cap - 1, f);
  buf[n] = '\0';
  std::fclose(f);
  return true;
}

ChildProcess::~ChildProcess() {
  if (_pid > 0 && running()) {
    ::kill(_pid, SIGKILL);
    int st;
    ::waitpid(_pid, &st, 0);
  }
}

bool ChildProcess::start(const char* const* argv, const char* stdoutPath, const char* stderrPath) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (stdoutPath)
    posix_spawn_file_actions_addopen(&fa, 1, stdoutPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (stderrPath)
    posix_spawn_file_actions_addopen(&fa, 2, stderrPath, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int rc =
      posix_spawnp(&_pid, argv[0], &fa, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&fa);
  _status = -1;
  if (rc != 0) {
    std::fprintf(stderr, "spawn %s: %s\n", argv[0], std::strerror(rc));
    _pid = -1;
    return false;
  }
  return true;
}

bool ChildProcess::running() {
  if (_pid <= 0 || _status >= 0) return false;
  int st = 0;
  const pid_t r = ::waitpid(_pid, &st, WNOHANG);
  if (r == 0) return true;
  if (r == _pid) _status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return false;
}

bool ChildProcess::wait(int timeoutMs, int* status) {
  const bool exited = waitFor([&] { return !running(); }, timeoutMs);
  if (exited && status) *status = _status;
  return exited;
}

void ChildProcess::signal(int sig) {
  if (_pid > 0 && running()) ::kill(_pid, sig);
}

int runToEnd(const char* const* argv, const char* stdoutPath, const char* stderrPath,
             int timeoutMs) {
  ChildProcess p;
  if (!p.start(argv, stdoutPath, stderrPath)) return kRunNotStarted;
  int status = kRunTimedOut;
  if (!p.wait(timeoutMs, &status)) {
    p.signal(SIGKILL);
    return kRunTimedOut;
  }
  return status;
}

PtyPair::PtyPair() {
  std::snprintf(_dir, sizeof _dir, "/tmp/cuetrack-pty-XXXXXX");
  if (!mkdtemp(_dir)) _dir[0] = '\0';
  std::snprintf(_a, sizeof _a, "%s/a", _dir);
  std::snprintf(_b, sizeof _b, "%s/b", _dir);
}

PtyPair::~PtyPair() {
  stop();
  ::unlink(_a);
  ::unlink(_b);
  ::rmdir(_dir);
}

bool PtyPair::start() {
  char ea[200], eb[200];
  std::snprintf(ea, sizeof ea, "PTY,raw,echo=0,link=%s", _a);
  std::snprintf(eb, sizeof eb, "PTY,raw,echo=0,link=%s", _b);
  const char* argv[] = {"socat", ea, eb, nullptr};
  if (!_socat.start(argv, nullptr, nullptr)) return false;
  return waitFor([&] { return fileExists(_a) && fileExists(_b); }, 5000);
}

void PtyPair::stop() {
  if (_socat.running()) {
    _socat.signal(SIGTERM);
    int st;
    if (!_socat.wait(5000, &st)) _socat.signal(SIGKILL);
    _socat.wait(5000, &st);
  }
  // socat removes its links on SIGTERM; make sure a stale one cannot confuse reopen tests.
  ::unlink(_a);
  ::unlink(_b);
}

std::string slurp(const std::string& path) {
  static char buf[1 << 20];
  if (!readFile(path.c_str(), buf, sizeof buf)) return "";
  return buf;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

}  // namespace cuetrack::test
