// What one benchmark call produces: for each tracker entry (a tracker, and for
// cuetrack a configuration), the figures per sequence, plus what the reports need.
#pragma once

#include <string>
#include <vector>

#include "Metrics.hpp"

namespace cuetrack::bench {

struct SequenceResult {
  std::string name;   // file or folder name without extension
  bool ran = false;   // false: the tracker could not run on it, or the sequence is broken
  std::string error;  // one line: why not
  // The sequence is at fault (no ground truth to start from, frames changing size): exit 1.
  // A tracker that cannot run on a sound sequence is a finding, not a failure.
  bool sequenceFault = false;
  // A --results file that could not be written (reported once; later runs write none).
  std::string outputError;
  Figures figures;
  int skippedFrames = 0;  // damaged or unreadable frames the reader skipped (--skip-bad-frames)
  // Mean overlap over runs for each evaluated frame, in frame order (plots, CSV).
  std::vector<int> frameIndex;
  std::vector<double> meanOverlap;
  // The boxes of the first run, one per frame of the sequence (--overlay).
  std::vector<Box> firstRunBoxes;
};

struct EntryResult {
  std::string tracker;  // "cuetrack", "opencv-kcf", ...
  std::string config;   // "1.1" ... "best" for cuetrack, "default" for peers
  int runs = 0;
  std::vector<SequenceResult> sequences;  // one per sequence, in command-line order
  std::string partial = "";  // "" for a whole run, else why it stopped early (a signal)

  std::string label() const {
    return config == "default" || config.empty() ? tracker : tracker + " " + config;
  }
  // Macro average over the sequences it ran on.
  Figures average() const;
  int sequencesRan() const;
};

}  // namespace cuetrack::bench
