#include "Runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "cuetrack/platform/linux/MonotonicClock.hpp"

namespace cuetrack::bench {

Frame CachedFrame::frame() const {
  Frame f;
  f.rgb = RgbView{rgb.data(), width, height, width};
  if (!depthMm.empty()) f.depthMm = DepthView{depthMm.data(), width, height, width};
  f.timeUs = timeUs;
  f.intrinsics = intrinsics;
  return f;
}

bool loadSequence(FrameSource& source, int maxFrames, size_t maxBytes, Sequence* seq,
                  std::string* err) {
  seq->name = source.name();
  seq->frames.clear();
  seq->bytes = 0;
  // The slot is 1.5 MiB: one for the whole process, reused.
  static FrameSlot slot;
  for (;;) {
    if (maxFrames > 0 && static_cast<int>(seq->frames.size()) >= maxFrames) break;
    slot.hasTruthMm = false;  // only sources that know the 3D truth set it
    const ReadStatus st = source.next(slot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) {
      *err = source.error();
      if (err->empty()) *err = seq->name + ": read error";
      return false;
    }
    CachedFrame f;
    f.index = slot.index;
    f.width = slot.rgb.width();
    f.height = slot.rgb.height();
    const size_t px = static_cast<size_t>(f.width) * static_cast<size_t>(f.height);
    f.rgb.assign(slot.rgb.data(), slot.rgb.data() + px);
    if (slot.hasDepth && slot.depthMm.width() == f.width && slot.depthMm.height() == f.height)
      f.depthMm.assign(slot.depthMm.data(), slot.depthMm.data() + px);
    f.timeUs = slot.timeUs;
    f.intrinsics = slot.intrinsics;
    f.hasGroundTruth = slot.hasGroundTruth;
    f.groundTruth = slot.groundTruth;
    f.hasTruthMm = slot.hasTruthMm;
    for (int a = 0; a < 3; ++a) f.truthCentreMm[a] = slot.truthCentreMm[a];
    if (px > 0) {
      const cv::Mat rgbMat(f.height, f.width, CV_8UC3, f.rgb.data());
      cv::cvtColor(rgbMat, f.bgr, cv::COLOR_RGB2BGR);
    }
    seq->bytes += px * (2 * sizeof(Rgb8)) + f.depthMm.size() * sizeof(uint16_t);
    seq->frames.push_back(std::move(f));
    if (seq->bytes > maxBytes) {
      *err = seq->name + ": more than " + std::to_string(maxBytes >> 20) +
             " MiB of decoded frames; cut it with --frames N";
      return false;
    }
  }
  seq->skippedFrames = source.skippedFrames();
  if (seq->frames.empty()) {
    *err = seq->name + ": no frames";
    return false;
  }
  return true;
}

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

void thinSequence(Sequence* seq, int stride, int dropPct, uint64_t seed) {
  if (stride <= 1 && dropPct <= 0) return;
  size_t initAt = seq->frames.size();
  for (size_t i = 0; i < seq->frames.size(); ++i)
    if (seq->frames[i].hasGroundTruth && !seq->frames[i].groundTruth.empty()) {
      initAt = i;
      break;
    }
  if (initAt == seq->frames.size()) return;  // runEntry reports it
  std::vector<CachedFrame> kept;
  kept.reserve(seq->frames.size());
  for (size_t i = 0; i < seq->frames.size(); ++i) {
    bool keep = i <= initAt;
    if (!keep && (i - initAt) % static_cast<size_t>(stride < 1 ? 1 : stride) == 0) {
      // splitmix64 of (seed, frame index): a fair draw per frame, reproducible.
      uint64_t h = seed * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(seq->frames[i].index);
      h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
      h ^= h >> 31;
      keep = static_cast<int>(h % 100) >= dropPct;
    }
    if (keep)
      kept.push_back(std::move(seq->frames[i]));
    else
      ++seq->droppedFrames;
  }
  seq->frames = std::move(kept);
}

bool sliceSequence(Sequence* seq, int fromIndex, int toIndex, bool reverse, std::string* err) {
  if (fromIndex < 0 && toIndex < 0 && !reverse) return true;
  const size_t before = seq->frames.size();
  std::vector<CachedFrame> kept;
  kept.reserve(before);
  for (CachedFrame& f : seq->frames)
    if ((fromIndex < 0 || f.index >= fromIndex) && (toIndex < 0 || f.index <= toIndex))
      kept.push_back(std::move(f));
  std::string suffix;
  if (fromIndex >= 0) suffix += ".from" + std::to_string(fromIndex);
  if (toIndex >= 0) suffix += ".to" + std::to_string(toIndex);
  if (reverse) suffix += ".rev";
  const std::string base = seq->name;
  seq->name += suffix;  // also when it fails: the tables then name the slice that failed
  if (kept.empty()) {
    *err = base + ": no frame has an index in " +
           (fromIndex < 0 ? std::string("0") : std::to_string(fromIndex)) + ".." +
           (toIndex < 0 ? std::string("end") : std::to_string(toIndex)) + " (of " +
           std::to_string(before) + " frames)";
    return false;
  }
  if (reverse) {
    uint64_t tMin = kept.front().timeUs, tMax = kept.front().timeUs;
    for (const CachedFrame& f : kept) {
      tMin = std::min(tMin, f.timeUs);
      tMax = std::max(tMax, f.timeUs);
    }
    std::reverse(kept.begin(), kept.end());
    for (CachedFrame& f : kept) f.timeUs = tMin + (tMax - f.timeUs);
  }
  seq->frames = std::move(kept);
  return true;
}

SequenceResult runEntry(const EntrySpec& spec, const Sequence& seq, const TrackerFactory& factory,
                        const RunOptions& options, Progress& progress) {
  SequenceResult result;
  result.skippedFrames = seq.skippedFrames;
  result.name = seq.name;

  // Initialisation at the first ground-truth box.
  size_t initAt = seq.frames.size();
  for (size_t i = 0; i < seq.frames.size(); ++i) {
    if (seq.frames[i].hasGroundTruth && !seq.frames[i].groundTruth.empty()) {
      initAt = i;
      break;
    }
  }
  if (initAt == seq.frames.size()) {
    result.error = "no ground-truth box to initialise from";
    result.sequenceFault = true;
    return result;
  }
  const CachedFrame& first = seq.frames[initAt];
  const int tracked = static_cast<int>(seq.frames.size() - initAt - 1);
  // A first box outside the image is the ground truth's fault, not the tracker's.
  {
    const Box& g = first.groundTruth;
    const float w = static_cast<float>(first.width), h = static_cast<float>(first.height);
    if (!(g.x < w && g.y < h && g.x + g.w > 0.f && g.y + g.h > 0.f)) {
      char box[160];
      std::snprintf(box, sizeof box,
                    "frame %d: ground-truth box %.0f,%.0f,%.0f,%.0f lies outside the %dx%d image",
                    first.index, static_cast<double>(g.x), static_cast<double>(g.y),
                    static_cast<double>(g.w), static_cast<double>(g.h), first.width, first.height);
      result.error = box;
      result.sequenceFault = true;
      return result;
    }
  }
  // A tracker given a frame of another size would skip it (cuetrack: still "tracking").
  for (size_t i = initAt + 1; i < seq.frames.size(); ++i) {
    const CachedFrame& f = seq.frames[i];
    if (f.width == first.width && f.height == first.height) continue;
    result.error = "frame " + std::to_string(f.index) + " is " + std::to_string(f.width) + "x" +
                   std::to_string(f.height) + ", the track began at " +
                   std::to_string(first.width) + "x" + std::to_string(first.height);
    result.sequenceFault = true;
    return result;
  }

  std::string err;
  std::unique_ptr<BenchTracker> tracker = factory(spec, &err);
  if (!tracker) {
    result.error = err;
    return result;
  }

  std::vector<RunFigures> runs;
  std::vector<double> frameTimesUs;
  std::vector<double> allocsPerRun;
  std::vector<double> overlapSum;
  double stageSumUs[5] = {0, 0, 0, 0, 0};
  long stageFrames = 0;
  std::vector<IndexedBox> boxes;
  boxes.reserve(seq.frames.size());
  frameTimesUs.reserve(static_cast<size_t>(tracked) * static_cast<size_t>(spec.runs));
  const platform::MonotonicClock clock;

  for (int run = 0; run < spec.runs; ++run) {
    if (!tracker->init(first, first.groundTruth, options.seed + static_cast<uint64_t>(run), &err)) {
      result.error = err;
      return result;
    }
    progress.beginRun(spec.tracker + (spec.config == "default" ? "" : " " + spec.config), run,
                      spec.runs, tracked);
    RunAccumulator acc;
    boxes.clear();
    for (size_t i = 0; i < initAt; ++i) boxes.push_back({seq.frames[i].index, Box{}});
    boxes.push_back({first.index, first.groundTruth});
    size_t evaluated = 0;
    uint64_t allocs = 0;
    for (size_t i = initAt + 1; i < seq.frames.size(); ++i) {
      const CachedFrame& f = seq.frames[i];
      double stageUs[5] = {0, 0, 0, 0, 0};
      const uint64_t a0 = options.allocationCount ? options.allocationCount() : 0;
      const uint64_t t0 = clock.nowUs();
      const Box box = tracker->update(f, stageUs);
      const uint64_t t1 = clock.nowUs();
      if (options.allocationCount) allocs += options.allocationCount() - a0;
      frameTimesUs.push_back(static_cast<double>(t1 - t0));
      for (int s = 0; s < 5; ++s) stageSumUs[s] += stageUs[s];
      ++stageFrames;
      boxes.push_back({f.index, box});
      if (f.hasGroundTruth) {
        const FrameEval e = evaluateFrame(f.groundTruth, box, tracker->lastHidden());
        acc.add(e);
        // 3D error where the target is visible and the tracker placed it in 3D.
        float posMm[3];
        if (f.hasTruthMm && !f.groundTruth.empty() && !box.empty() &&
            tracker->lastPositionMm(posMm))
          acc.addPosition(f.truthCentreMm, posMm);
        if (run == 0) {
          result.frameIndex.push_back(f.index);
          overlapSum.push_back(0.0);
        }
        if (evaluated < overlapSum.size()) overlapSum[evaluated] += e.overlap;
        ++evaluated;
      }
      progress.tick(static_cast<int>(i - initAt));
    }
    progress.endRun();
    runs.push_back(acc.figures());
    if (run == 0)
      for (const IndexedBox& b : boxes) result.firstRunBoxes.push_back(b.box);
    allocsPerRun.push_back(static_cast<double>(allocs));
    if (!options.resultsDir.empty() && result.outputError.empty()) {
      const std::string dir = options.resultsDir + "/" + seq.name;
      const std::string label =
          spec.config == "default" ? spec.tracker : spec.tracker + "-" + spec.config;
      const std::string path = dir + "/" + label + ".run" + std::to_string(run + 1) + ".txt";
      std::string werr;
      const std::string header = seq.gtHeader.empty() ? "./" + seq.name : seq.gtHeader;
      if (!makeDirs(dir, &werr) ||
          !writeBobotResult(path, header, boxes, first.width, first.height, &werr)) {
        std::fprintf(stderr, "cuetrack-bench: %s\n", werr.c_str());
        result.outputError = werr;
      }
    }
  }

  result.ran = true;
  result.figures = aggregateRuns(runs, frameTimesUs, allocsPerRun);
  result.figures.hasStages = tracker->hasStages();
  if (stageFrames > 0)
    for (int s = 0; s < 5; ++s) result.figures.stageMs[s] = stageSumUs[s] / stageFrames / 1000.0;
  result.meanOverlap.resize(overlapSum.size());
  for (size_t i = 0; i < overlapSum.size(); ++i) result.meanOverlap[i] = overlapSum[i] / spec.runs;
  return result;
}

}  // namespace cuetrack::bench
