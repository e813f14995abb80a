// Test helpers that touch the OS: child processes (posix_spawn) and a socat pty
// pair. Waiting is bounded polling on an observable condition, never a fixed sleep
// used as synchronisation.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace cuetrack::test {

// Polls `done` every ~5 ms until it returns true or timeoutMs passes.
template <typename F>
bool waitFor(F done, int timeoutMs);
void pauseMs(int ms);  // one short poll interval (used only inside waitFor-style loops)

class ChildProcess {
 public:
  ChildProcess() = default;
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  // argv ends with nullptr. stdout/stderr go to the files named (nullptr = inherit).
  bool start(const char* const* argv, const char* stdoutPath, const char* stderrPath);
  // Waits up to timeoutMs for exit; true when exited, *status = exit code
  // (128 + signal when killed by one).
  bool wait(int timeoutMs, int* status);
  bool running();
  void signal(int sig);
  pid_t pid() const { return _pid; }

 private:
  pid_t _pid{-1};
  int _status{-1};
};

// Runs argv (ending with nullptr) to completion: its exit status; kRunTimedOut when it did
// not end within timeoutMs (it is then killed), kRunNotStarted when it could not start.
inline constexpr int kRunTimedOut = -1, kRunNotStarted = -2;
int runToEnd(const char* const* argv, const char* stdoutPath, const char* stderrPath,
             int timeoutMs);

// socat PTY,raw,echo=0,link=DIR/a  PTY,raw,echo=0,link=DIR/b
class PtyPair {
 public:
  PtyPair();  // creates a private temporary folder for the links
  ~PtyPair();
  bool start();  // spawns socat and waits (bounded) for both links
  void stop();   // SIGTERM by PID, waits for exit; the links disappear
  bool running() { return _socat.running(); }
  const char* a() const { return _a; }
  const char* b() const { return _b; }
  const char* dir() const { return _dir; }

 private:
  ChildProcess _socat;
  char _dir[128]{};
  char _a[160]{};
  char _b[160]{};
};

bool fileExists(const char* path);
// Reads a whole small text file into buf; false when it cannot be read.
bool readFile(const char* path, char* buf, size_t cap);
// A whole text file (up to 1 MiB) as a string; "" when it cannot be read.
std::string slurp(const std::string& path);
// The lines of `text`, without their newlines.
std::vector<std::string> lines(const std::string& text);

template <typename F>
bool waitFor(F done, int timeoutMs) {
  for (int waited = 0; waited <= timeoutMs; waited += 5) {
    if (done()) return true;
    pauseMs(5);
  }
  return done();
}

}  // namespace cuetrack::test
