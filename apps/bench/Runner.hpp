// Runs tracker entries over a decoded sequence (Sequence.hpp), the paper's protocol:
// initialise at the first ground-truth box, track every later frame, score every later
// frame that has a ground-truth line, repeat for each run (seed), average. Only the
// update call is timed.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Outputs.hpp"
#include "Results.hpp"
#include "Sequence.hpp"
#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::bench {

// One tracker as the runner sees it.
class BenchTracker {
 public:
  virtual ~BenchTracker() = default;
  // Starts run with `seed` at frame f with the ground-truth box; false with *err when
  // the tracker cannot run on this input (the reason is reported, not hidden).
  virtual bool init(const CachedFrame& f, const Box& box, uint64_t seed, std::string* err) = 0;
  // Estimate for frame f (empty = no target reported). stageUs[5]: features, predict,
  // weigh, learn, total, filled by trackers that time their stages.
  virtual Box update(const CachedFrame& f, double stageUs[5]) = 0;
  virtual bool hasStages() const { return false; }
  // The 3D centre [mm] (camera coordinates) the last update reported; false when it
  // reported none (a 2D tracker, or no target).
  virtual bool lastPositionMm(float /*out*/[3]) const { return false; }
  // The last update's box is where the target was last seen, now hidden behind something
  // (cuetrack's occluded flag): right, not wrong, when the target is not visible.
  virtual bool lastHidden() const { return false; }
};

struct EntrySpec {
  std::string tracker;  // "cuetrack", "opencv-kcf", ...
  std::string config;   // "1.1" ... "best"; "default" for peers
  int runs = 10;
};

using TrackerFactory =
    std::function<std::unique_ptr<BenchTracker>(const EntrySpec&, std::string* err)>;

// Stderr progress: sequence, tracker, run, frame, fps, time left for this sequence.
class Progress {
 public:
  explicit Progress(bool enabled);
  void beginSequence(const std::string& name, int index, int count, long plannedUpdates);
  void beginRun(const std::string& label, int run, int runs, int frames);
  void tick(int frame);
  void endRun();

 private:
  void print(bool force);
  bool _enabled;
  bool _tty;
  std::string _seq, _label;
  int _seqIndex = 0, _seqCount = 0, _run = 0, _runs = 0, _frame = 0, _frames = 0;
  long _planned = 0, _done = 0;
  double _seqStartS = 0, _lastPrintS = 0;
};

struct RunOptions {
  uint64_t seed = 1;
  std::string resultsDir;  // BoBoT result files, one per run; empty = none
  // Heap allocations of the process so far (the bench links a counting allocator);
  // nullptr: allocations are not counted and reported as 0.
  uint64_t (*allocationCount)() = nullptr;
};

// Runs one entry on one sequence; never throws; a stop signal (platform::stopRequested)
// ends it after the runs completed so far (none: ran = false, "interrupted ..."); a tracker that
// cannot run, or a sequence whose frames change size after the initialisation frame, gives ran =
// false with the reason. A --results file that cannot be written is reported on stderr and set in
// outputError.
SequenceResult runEntry(const EntrySpec& spec, const Sequence& seq, const TrackerFactory& factory,
                        const RunOptions& options, Progress& progress);

}  // namespace cuetrack::bench
