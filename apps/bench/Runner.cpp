#include "Runner.hpp"

#include <unistd.h>

#include <cstdio>

#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

namespace cuetrack::bench {

namespace {

double nowS() {
  static const platform::MonotonicClock clock;
  return static_cast<double>(clock.nowUs()) * 1e-6;
}

}  // namespace

Progress::Progress(bool enabled) : _enabled(enabled), _tty(::isatty(2) != 0) {}

void Progress::beginSequence(const std::string& name, int index, int count, long plannedUpdates) {
  _seq = name;
  _seqIndex = index;
  _seqCount = count;
  _planned = plannedUpdates;
  _done = 0;
  _seqStartS = nowS();
}

void Progress::beginRun(const std::string& label, int run, int runs, int frames) {
  _label = label;
  _run = run;
  _runs = runs;
  _frame = 0;
  _frames = frames;
}

void Progress::tick(int frame) {
  _frame = frame;
  ++_done;
  if (_enabled && _tty && nowS() - _lastPrintS > 0.25) print(false);
}

void Progress::endRun() {
  if (!_enabled) return;
  print(true);
}

void Progress::print(bool endOfRun) {
  _lastPrintS = nowS();
  const double elapsed = _lastPrintS - _seqStartS;
  const double fps = elapsed > 0 ? _done / elapsed : 0.0;
  const double leftS = fps > 0 ? (_planned - _done) / fps : 0.0;
  const int left = static_cast<int>(leftS + 0.5);
  char line[256];
  std::snprintf(line, sizeof line,
                "[seq %d/%d %s] %s run %d/%d frame %d/%d  %.1f fps  %d:%02d left", _seqIndex + 1,
                _seqCount, _seq.c_str(), _label.c_str(), _run + 1, _runs, _frame, _frames, fps,
                left / 60, left % 60);
  if (_tty)
    std::fprintf(stderr, "\r\033[K%s%s", line, endOfRun ? "" : "");
  else if (endOfRun)
    std::fprintf(stderr, "%s\n", line);
  if (_tty && endOfRun && _done >= _planned) std::fprintf(stderr, "\n");
}

namespace {

// The first frame with a ground-truth box (where every run starts), or frames.size().
size_t firstTruthFrame(const Sequence& seq) {
  for (size_t i = 0; i < seq.frames.size(); ++i)
    if (seq.frames[i].hasGroundTruth && !seq.frames[i].groundTruth.empty()) return i;
  return seq.frames.size();
}

// Why the sequence cannot be run from frame initAt, "" when it can: these are the
// sequence's faults, not the tracker's.
std::string sequenceFault(const Sequence& seq, size_t initAt) {
  if (initAt == seq.frames.size())
    return "no ground-truth box to initialise from (a video's NAME.gt.txt or NAME.txt beside "
           "it, a folder's own file, or --gt FILE before the sequence)";
  const CachedFrame& first = seq.frames[initAt];
  const Box& g = first.groundTruth;
  const float w = static_cast<float>(first.width), h = static_cast<float>(first.height);
  if (!(g.x < w && g.y < h && g.x + g.w > 0.f && g.y + g.h > 0.f)) {
    char box[160];
    std::snprintf(box, sizeof box,
                  "frame %d: ground-truth box %.0f,%.0f,%.0f,%.0f lies outside the %dx%d image",
                  first.index, static_cast<double>(g.x), static_cast<double>(g.y),
                  static_cast<double>(g.w), static_cast<double>(g.h), first.width, first.height);
    return box;
  }
  // A tracker given a frame of another size would skip it (cuetrack: still "tracking").
  for (size_t i = initAt + 1; i < seq.frames.size(); ++i) {
    const CachedFrame& f = seq.frames[i];
    if (f.width == first.width && f.height == first.height) continue;
    return "frame " + std::to_string(f.index) + " is " + std::to_string(f.width) + "x" +
           std::to_string(f.height) + ", the track began at " + std::to_string(first.width) + "x" +
           std::to_string(first.height);
  }
  return "";
}

// What the runs of one entry add up to.
struct EntryTally {
  std::vector<RunFigures> runs;
  std::vector<double> frameTimesUs;
  std::vector<double> allocsPerRun;
  std::vector<double> overlapSum;  // per scored frame, over the runs
  double stageSumUs[5] = {0, 0, 0, 0, 0};
  long stageFrames = 0;
};

// One run: tracks every frame after initAt, timing each update, and scores the frames
// with ground truth. boxes gets the run's box on every frame; run 0 also fills the
// result's scored frame indices. False when a stop signal ended it early: its figures are
// then left out.
bool trackRun(BenchTracker& tracker, const Sequence& seq, size_t initAt, int run,
              const RunOptions& options, Progress& progress, EntryTally* tally,
              std::vector<IndexedBox>* boxes, SequenceResult* result) {
  static const platform::MonotonicClock clock;
  const CachedFrame& first = seq.frames[initAt];
  RunAccumulator acc;
  boxes->clear();
  for (size_t i = 0; i < initAt; ++i) boxes->push_back({seq.frames[i].index, Box{}});
  boxes->push_back({first.index, first.groundTruth});
  uint64_t allocs = 0;
  std::vector<double> overlaps;  // this run's, added to the tally when it completes
  for (size_t i = initAt + 1; i < seq.frames.size(); ++i) {
    if (platform::stopRequested()) return false;
    const CachedFrame& f = seq.frames[i];
    double stageUs[5] = {0, 0, 0, 0, 0};
    const uint64_t a0 = options.allocationCount ? options.allocationCount() : 0;
    const uint64_t t0 = clock.nowUs();
    const Box box = tracker.update(f, stageUs);
    const uint64_t t1 = clock.nowUs();
    if (options.allocationCount) allocs += options.allocationCount() - a0;
    tally->frameTimesUs.push_back(static_cast<double>(t1 - t0));
    for (int s = 0; s < 5; ++s) tally->stageSumUs[s] += stageUs[s];
    ++tally->stageFrames;
    boxes->push_back({f.index, box});
    if (f.hasGroundTruth) {
      const FrameEval e = evaluateFrame(f.groundTruth, box, tracker.lastHidden());
      acc.add(e);
      // 3D error where the target is visible and the tracker placed it in 3D.
      float posMm[3];
      if (f.hasTruthMm && !f.groundTruth.empty() && !box.empty() && tracker.lastPositionMm(posMm))
        acc.addPosition(f.truthCentreMm, posMm);
      if (run == 0) result->frameIndex.push_back(f.index);
      overlaps.push_back(e.overlap);
    }
    progress.tick(static_cast<int>(i - initAt));
  }
  tally->runs.push_back(acc.figures());
  tally->allocsPerRun.push_back(static_cast<double>(allocs));
  if (tally->overlapSum.empty()) tally->overlapSum.assign(overlaps.size(), 0.0);
  for (size_t k = 0; k < overlaps.size() && k < tally->overlapSum.size(); ++k)
    tally->overlapSum[k] += overlaps[k];
  return true;
}

// --results: the run's boxes as a BoBoT result file; a failure is reported once, in
// result->outputError, and no later run tries again.
void writeRunResult(const EntrySpec& spec, const Sequence& seq, const CachedFrame& first, int run,
                    const std::vector<IndexedBox>& boxes, const RunOptions& options,
                    SequenceResult* result) {
  if (options.resultsDir.empty() || !result->outputError.empty()) return;
  const std::string dir = options.resultsDir + "/" + seq.name;
  const std::string label =
      spec.config == "default" ? spec.tracker : spec.tracker + "-" + spec.config;
  const std::string path = dir + "/" + label + ".run" + std::to_string(run + 1) + ".txt";
  std::string werr;
  const std::string header = seq.gtHeader.empty() ? "./" + seq.name : seq.gtHeader;
  if (!makeDirs(dir, &werr) ||
      !writeBobotResult(path, header, boxes, first.width, first.height, &werr)) {
    std::fprintf(stderr, "cuetrack-bench: %s\n", werr.c_str());
    result->outputError = werr;
  }
}

}  // namespace

SequenceResult runEntry(const EntrySpec& spec, const Sequence& seq, const TrackerFactory& factory,
                        const RunOptions& options, Progress& progress) {
  SequenceResult result;
  result.skippedFrames = seq.skippedFrames;
  result.name = seq.name;

  const size_t initAt = firstTruthFrame(seq);  // initialisation at the first ground-truth box
  result.error = sequenceFault(seq, initAt);
  if (!result.error.empty()) {
    result.sequenceFault = true;
    return result;
  }
  const CachedFrame& first = seq.frames[initAt];
  const int tracked = static_cast<int>(seq.frames.size() - initAt - 1);

  std::string err;
  std::unique_ptr<BenchTracker> tracker = factory(spec, &err);
  if (!tracker) {
    result.error = err;
    return result;
  }

  EntryTally tally;
  std::vector<IndexedBox> boxes;
  boxes.reserve(seq.frames.size());
  tally.frameTimesUs.reserve(static_cast<size_t>(tracked) * static_cast<size_t>(spec.runs));
  for (int run = 0; run < spec.runs; ++run) {
    if (!tracker->init(first, first.groundTruth, options.seed + static_cast<uint64_t>(run), &err)) {
      result.error = err;
      return result;
    }
    progress.beginRun(spec.tracker + (spec.config == "default" ? "" : " " + spec.config), run,
                      spec.runs, tracked);
    if (!trackRun(*tracker, seq, initAt, run, options, progress, &tally, &boxes, &result)) {
      progress.endRun();
      break;  // a stop signal: the runs completed so far count
    }
    progress.endRun();
    if (run == 0)
      for (const IndexedBox& b : boxes) result.firstRunBoxes.push_back(b.box);
    writeRunResult(spec, seq, first, run, boxes, options, &result);
  }

  const size_t completed = tally.runs.size();
  if (completed == 0) {
    result.error = "interrupted before its first run ended";
    result.frameIndex.clear();
    return result;
  }
  result.ran = true;
  result.figures = aggregateRuns(tally.runs, tally.frameTimesUs, tally.allocsPerRun);
  result.figures.hasStages = tracker->hasStages();
  if (tally.stageFrames > 0)
    for (int s = 0; s < 5; ++s)
      result.figures.stageMs[s] = tally.stageSumUs[s] / tally.stageFrames / 1000.0;
  result.meanOverlap.resize(tally.overlapSum.size());
  for (size_t i = 0; i < tally.overlapSum.size(); ++i)
    result.meanOverlap[i] = tally.overlapSum[i] / static_cast<double>(completed);
  return result;
}

}  // namespace cuetrack::bench
