// Clean stop on SIGINT/SIGTERM: the handler only sets a flag that the main loop
// polls (nothing else is async-signal-safe). SIGPIPE and SIGXFSZ are ignored so a
// closed stdout pipe or a file-size limit (ulimit -f) becomes a write error (EPIPE,
// EFBIG) that the program reports, instead of a silent death.
#pragma once

namespace cuetrack::platform {

void ignoreWriteSignals();  // SIGPIPE, SIGXFSZ; every program that writes calls it
// SIGINT, SIGTERM, SIGHUP (unblocked, so one already pending is seen), and
// ignoreWriteSignals(). Every tool calls it first thing: a stop at any moment ends the tool
// with its final line and its documented exit code.
void installStopSignals();
bool stopRequested();
int stopSignal();  // the signal that asked to stop, 0 if none

}  // namespace cuetrack::platform
