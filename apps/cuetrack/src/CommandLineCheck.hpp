// cuetrack's first step: the command line and all that can be refused before anything
// opens (exit 2), and what the later steps ask of it (a target's ways in, a live camera).
#pragma once

#include <cstdint>

#include "Options.hpp"
#include "cuetrack/platform/Reporter.hpp"

namespace cuetrack::app {

// A step's "no exit code yet": the run goes on.
constexpr int kGoOn = -1;

// How a target can be given, for the line that says none can arrive.
constexpr const char* kWaysToATarget =
    "give --box X,Y,W,H, --select, or a link for a START (--serial DEV, --mavlink-udp "
    "HOST:PORT)";

// A target can come from the user: a box, a drag, or a START on a link.
bool userTargetPossible(const AppOptions& opt);

// --source kinect or kinect:colour: a live camera, which has no ground truth.
bool liveCamera(const AppOptions& opt);

// A bad option, a readable signing key, an output that is also an input, a baud rate, a
// view or a camera this build lacks: kExitUsage (or --help's code) after its line, else
// kGoOn. Fills key with the MAVLink signing key when one is given.
int checkCommandLine(int argc, char** argv, AppOptions& opt, uint8_t (&key)[32],
                     platform::Reporter& reporter);

}  // namespace cuetrack::app
