// Runs tracker entries over a decoded sequence, the paper's protocol: initialise at
// the first ground-truth box, track every later frame, score every later frame that
// has a ground-truth line, repeat for each run (seed), average.
//
// The sequence is decoded once into memory (Sequence), so every tracker sees the very
// same frames and decoding never enters the timings. Only the update call is timed.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "Outputs.hpp"
#include "Results.hpp"
#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::bench {

// One decoded frame, stored compactly (a FrameSlot is 1.5 MiB whatever the size).
struct CachedFrame {
  int index = 0;
  int width = 0, height = 0;  // [px] of rgb
  std::vector<Rgb8> rgb;
  std::vector<uint16_t> depthMm;  // empty when the source has no depth
  uint64_t timeUs = 0;
  CameraIntrinsics intrinsics{};
  bool hasGroundTruth = false;
  Box groundTruth{};
  bool hasTruthMm = false;  // the target's true 3D centre is known (synthetic scenes)
  float truthCentreMm[3] = {0.f, 0.f, 0.f};
  cv::Mat bgr;  // the same pixels for the OpenCV peers, converted once, outside the timings

  bool hasColour() const { return width > 0 && height > 0 && !rgb.empty(); }
  Frame frame() const;
};

struct Sequence {
  std::string name;
  std::string gtHeader;  // first line of the ground-truth file, for BoBoT result files
  std::vector<CachedFrame> frames;
  int skippedFrames = 0;
  int droppedFrames = 0;  // by thinSequence
  size_t bytes = 0;
};

// Decodes up to `maxFrames` (<= 0: all) frames. False with one line in *err when the
// source fails or the frames would exceed `maxBytes` of memory.
bool loadSequence(FrameSource& source, int maxFrames, size_t maxBytes, Sequence* seq,
                  std::string* err);

// A slower or lossier camera, from the same recording: after the first ground-truth frame
// (where trackers start) keeps every stride-th frame, and of those drops dropPct percent
// at random (the same frames for every tracker and run: a hash of seed and frame index).
// The kept frames keep their timestamps, so a tracker sees the gaps; dropped frames are
// neither tracked nor scored.
void thinSequence(Sequence* seq, int stride, int dropPct, uint64_t seed);

// Another start and direction from the same recording (OTB's temporal robustness
// protocol, and a target that moves the other way): keeps the frames whose index lies in
// [fromIndex, toIndex] (< 0: no bound), then, with `reverse`, plays them backwards, so
// the track begins at the last ground-truth box. Reversed timestamps are mirrored
// (t' = tMin + tMax - t) so they still increase with the same gaps; frame indices stay
// the recording's. The name gets ".fromF", ".toT", ".rev" so tables and output
// files say what was run (also on failure). False with one line in *err when no frame
// is left.
bool sliceSequence(Sequence* seq, int fromIndex, int toIndex, bool reverse, std::string* err);

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

// Runs one entry on one sequence; never throws; a tracker that cannot run, or a
// sequence whose frames change size after the initialisation frame, gives ran = false
// with the reason. A --results file that cannot be written is reported on stderr and
// set in outputError.
SequenceResult runEntry(const EntrySpec& spec, const Sequence& seq, const TrackerFactory& factory,
                        const RunOptions& options, Progress& progress);

}  // namespace cuetrack::bench
