// The paper's evaluation protocol (García et al. 2012, Sec. 3; Klein et al.'s BoBoT
// metrics; PROST's PASCAL score and centre distance), as plain functions so tests can
// check them on hand-computed cases.
//
// Per evaluated frame (one that has a ground-truth line):
//   overlap  = |GT ∩ P| / |GT ∪ P|, 0 when either box is empty; a frame whose
//              ground truth is empty ("0 0 0 0": target not visible) counts, with 0;
//   hit      = overlap > 1/3;   pascal = overlap > 0.5;
//   centre distance [px] between box centres, only where BOTH boxes are non-empty:
//              a frame where either is empty has no defined distance, so it is left
//              out of the mean (it already scores 0 in overlap, hit and pascal).
//   3D centre error [mm]: |true centre - reported 3D centre|, on sources that know the
//              target's 3D centre (synthetic scenes), only where the target is visible
//              and the tracker reported a 3D position (3D presets while tracking).
// Per run: mean overlap, hit rate and pascal score in percent (0-100), mean centre
// distance over the frames that have one, mean 3D centre error likewise (NaN when there
// is none).
// Over runs (seeds): plain means of the per-run figures (runs without a centre
// distance are skipped); times pool every frame of every run.
// OTB's one-pass curves (Wu et al. 2013), per run then averaged like the rest:
//   success(t)   = share of evaluated frames with overlap > t, t = 0, 0.05, ..., 1;
//                  its area under the curve (AUC) is the mean over those 21 thresholds;
//   precision(t) = share of evaluated frames with a centre distance <= t px,
//                  t = 0 .. 50; a frame without a distance (either box empty) is a miss;
//                  read at 20 px.
#pragma once

#include <cstdint>
#include <vector>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::bench {

inline constexpr double kHitThreshold = 1.0 / 3.0;
inline constexpr double kPascalThreshold = 0.5;
inline constexpr int kSuccessSteps = 21;    // overlap thresholds 0, 0.05, ..., 1
inline constexpr int kPrecisionSteps = 51;  // centre-distance thresholds 0 .. 50 px
inline constexpr int kPrecisionAtPx = 20;   // the field's single precision figure

double overlapDouble(const Box& a, const Box& b);  // IoU, 0 when either is empty

struct FrameEval {
  double overlap = 0.0;        // [0, 1]
  bool hasCenterDist = false;  // both boxes non-empty
  double centerDistPx = 0.0;   // [px], valid when hasCenterDist
};
// A frame whose truth is empty (the target hidden or out of view) scores 1 when the
// tracker reports no visible target (no box, or a box it flags as hidden behind something:
// `hidden`) and 0 when it reports one, as long-term tracking scores absence (VOT-LT,
// OxUvA): a robot must know when its target is gone.
FrameEval evaluateFrame(const Box& groundTruth, const Box& predicted, bool hidden = false);
// Names the scoring rule in the peer cache's key: a result scored by an older rule is
// never read. Change it with any change to how a frame is scored.
inline constexpr const char* kScoringRule = "absence-scored";

// Figures of one run over one sequence.
struct RunFigures {
  int frames = 0;           // evaluated frames
  double overlapPct = 0.0;  // mean overlap x 100
  double hitPct = 0.0;
  double pascalPct = 0.0;
  double centerPx = 0.0;   // NaN when no frame had both boxes
  int centerFrames = 0;    // frames that entered centerPx
  double centerMm = 0.0;   // NaN when no frame had a 3D position and 3D truth
  double centerZMm = 0.0;  // mean |z error| over the same frames
  int centerMmFrames = 0;
  double success[kSuccessSteps] = {};      // [0, 1]
  double precision[kPrecisionSteps] = {};  // [0, 1]
};

class RunAccumulator {
 public:
  void add(const Box& groundTruth, const Box& predicted, bool hidden = false);
  void add(const FrameEval& e);         // a frame the caller evaluated already
  void addOverlapOnly(double overlap);  // for callers that evaluated the frame already
  // A frame's 3D centre: truth and estimate [mm], camera coordinates.
  void addPosition(const float truthMm[3], const float estimateMm[3]);
  RunFigures figures() const;
  int frames() const { return _frames; }

 private:
  int _frames = 0;
  double _overlapSum = 0.0;
  int _hits = 0;
  int _pascals = 0;
  double _centerSum = 0.0;
  int _centerFrames = 0;
  double _centerMmSum = 0.0, _centerZMmSum = 0.0;
  int _centerMmFrames = 0;
  int _successFrames[kSuccessSteps] = {};
  int _precisionFrames[kPrecisionSteps] = {};
};

// The figures the JSON schema and the tables carry, for one sequence or an average.
struct Figures {
  int frames = 0;           // evaluated frames per run (sum over sequences for an average)
  double overlap = 0.0;     // [%]
  double hit = 0.0;         // [%]
  double pascal = 0.0;      // [%]
  double centerPx = 0.0;    // [px], NaN = undefined
  double centerPct = 0.0;   // frames centerPx is over (both boxes exist) [% of frames]
  double centerMm = 0.0;    // 3D centre error [mm], NaN = undefined (no 3D truth or position)
  double centerZMm = 0.0;   // its z part, mean |z error| [mm], NaN likewise
  double msMedian = 0.0;    // tracking time per frame [ms]
  double msMean = 0.0;      // [ms]
  double allocs = 0.0;      // heap allocations while tracking, per run
  double stageMs[5] = {0};  // cuetrack only: features, predict, weigh, learn, total (mean)
  bool hasStages = false;
  double auc = 0.0;                        // area under the success curve [%]
  double precision20 = 0.0;                // precision at kPrecisionAtPx [%]
  double success[kSuccessSteps] = {};      // mean curve over runs (sequences) [0, 1]
  double precision[kPrecisionSteps] = {};  // likewise
  // Mean overlap of each run (seed) [%]; for an average, of each seed over the sequences
  // (the mean of the sequences' k-th runs). Their sample standard deviation is the
  // seed-to-seed spread: a change is real only when it moves the mean by more.
  std::vector<double> runOverlap;
  double overlapSpread() const;  // [%], 0 with fewer than 2 runs
};

// Means over runs; `frameTimesUs` pools every tracked frame of every run.
Figures aggregateRuns(const std::vector<RunFigures>& runs, const std::vector<double>& frameTimesUs,
                      const std::vector<double>& allocsPerRun);
// Macro average over sequences, as the paper's "Averages" columns: the mean of the
// per-sequence figures (centre distances over the sequences that have one).
Figures averageFigures(const std::vector<Figures>& sequences);

double median(std::vector<double> values);  // 0 for none

}  // namespace cuetrack::bench
