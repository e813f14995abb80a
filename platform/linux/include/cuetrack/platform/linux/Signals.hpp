// Clean stop on SIGINT/SIGTERM: the handler only sets a flag that the main loop
// polls (nothing else is async-signal-safe). SIGPIPE is ignored so a closed stdout
// pipe becomes a write error we report instead of a silent death.
#pragma once

namespace cuetrack::platform {

void installStopSignals();
bool stopRequested();
int stopSignal();  // the signal that asked to stop, 0 if none

}  // namespace cuetrack::platform
