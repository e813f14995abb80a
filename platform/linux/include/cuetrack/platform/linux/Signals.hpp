// Clean stop on SIGINT/SIGTERM: the handler only sets a flag that the main loop
// polls (nothing else is async-signal-safe). SIGPIPE and SIGXFSZ are ignored so a
// closed stdout pipe or a file-size limit (ulimit -f) becomes a write error (EPIPE,
// EFBIG) that the program reports, instead of a silent death.
#pragma once

namespace cuetrack::platform {

void ignoreWriteSignals();  // SIGPIPE, SIGXFSZ; every program that writes calls it
void installStopSignals();  // SIGINT, SIGTERM, and ignoreWriteSignals()
bool stopRequested();
int stopSignal();  // the signal that asked to stop, 0 if none

}  // namespace cuetrack::platform
