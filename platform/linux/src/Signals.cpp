#include "cuetrack/platform/linux/Signals.hpp"

#include <signal.h>

namespace cuetrack::platform {
namespace {
// Process-wide by nature: a signal handler can reach nothing else.
volatile sig_atomic_t gStopSignal = 0;

void onStop(int sig) {
  gStopSignal = sig;
}
}  // namespace

void ignoreWriteSignals() {
  struct sigaction ign {};
  ign.sa_handler = SIG_IGN;
  sigemptyset(&ign.sa_mask);
  sigaction(SIGPIPE, &ign, nullptr);
  sigaction(SIGXFSZ, &ign, nullptr);
}

void installStopSignals() {
  struct sigaction sa {};
  sa.sa_handler = onStop;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a blocking poll/read returns EINTR and the loop sees the flag
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGHUP, &sa, nullptr);  // the terminal or ssh session went: stop as cleanly
  // A stop signal that came before this (blocked by a parent: a service manager, a test)
  // is delivered now, to the handler, rather than lost or fatal.
  sigset_t stops;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  sigaddset(&stops, SIGHUP);
  sigprocmask(SIG_UNBLOCK, &stops, nullptr);
  ignoreWriteSignals();
}

bool stopRequested() {
  return gStopSignal != 0;
}
int stopSignal() {
  return gStopSignal;
}

}  // namespace cuetrack::platform
