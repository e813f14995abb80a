// What cuetrack tells its user on stderr at the start and the end of a run: the banner
// (the source and why, the target, where tracks go) and the closing lines (why it stopped,
// what the link managed, the tracking summary, the next commands to try).
#pragma once

#include <cstdint>

#include "Options.hpp"
#include "Pipeline.hpp"
#include "RunSummary.hpp"
#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackLink.hpp"

namespace cuetrack::app {

// How the run's loop ended.
struct RunEnd {
  StepResult result = StepResult::Continue;
  bool windowQuit = false;  // q, Esc or the window closed
  uint64_t runUs = 0;       // the loop's wall time
};

// The link as the status and closing lines name it.
const char* linkName(const AppOptions& opt);

// One line at start. groundTruth: the source's first frame has ground truth (the banner
// names its file only then). stdoutIsTerminal: tracks go to stdout only with --stdout.
void printBanner(const AppOptions& opt, const char* groundTruthName, bool groundTruth,
                 bool stdoutIsTerminal, platform::Reporter& reporter);

// The closing lines; with --quiet only what would otherwise be lost without a word
// (skipped frames, dropped or refused messages). link may be null. A failed run (failed:
// its exit code is not 0; its error is said already) gets no summary and no next: line,
// only how far it got when it tracked anything.
void printSummary(const AppOptions& opt, const char* program, const Pipeline& pipeline,
                  const FrameSource& source, const platform::TrackLink* link,
                  const RunSummary& summary, const RunEnd& end, uint64_t windowDroppedFrames,
                  bool failed, platform::Reporter& reporter);

}  // namespace cuetrack::app
