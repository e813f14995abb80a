// The whole `cuetrack` program except the choice of tracker: parses the command
// line, opens the source and outputs, runs the pipeline, returns the exit code.
#pragma once

#include "TrackerPort.hpp"

namespace cuetrack::app {

int runCuetrack(int argc, char** argv, TrackerPort& tracker);

}  // namespace cuetrack::app
