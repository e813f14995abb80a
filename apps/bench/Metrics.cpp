#include "Metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cuetrack::bench {

// Same definition as cuetrack::overlap(), in double so that thresholds on exact
// fractions (1/3, 1/2) are decided by the geometry, not by float rounding.
double overlapDouble(const Box& a, const Box& b) {
  if (a.empty() || b.empty()) return 0.0;
  const double x0 = std::max<double>(a.x, b.x), y0 = std::max<double>(a.y, b.y);
  const double x1 = std::min<double>(double(a.x) + a.w, double(b.x) + b.w);
  const double y1 = std::min<double>(double(a.y) + a.h, double(b.y) + b.h);
  if (x1 <= x0 || y1 <= y0) return 0.0;
  const double inter = (x1 - x0) * (y1 - y0);
  return inter / (double(a.w) * a.h + double(b.w) * b.h - inter);
}

FrameEval evaluateFrame(const Box& groundTruth, const Box& predicted, bool hidden) {
  FrameEval e;
  if (groundTruth.empty()) {
    e.overlap = predicted.empty() || hidden ? 1.0 : 0.0;
    return e;
  }
  e.overlap = overlapDouble(groundTruth, predicted);
  if (!groundTruth.empty() && !predicted.empty()) {
    const double dx = (double(groundTruth.x) + 0.5 * double(groundTruth.w)) -
                      (double(predicted.x) + 0.5 * double(predicted.w));
    const double dy = (double(groundTruth.y) + 0.5 * double(groundTruth.h)) -
                      (double(predicted.y) + 0.5 * double(predicted.h));
    e.hasCenterDist = true;
    e.centerDistPx = std::sqrt(dx * dx + dy * dy);
  }
  return e;
}

void RunAccumulator::add(const Box& groundTruth, const Box& predicted, bool hidden) {
  add(evaluateFrame(groundTruth, predicted, hidden));
}

void RunAccumulator::add(const FrameEval& e) {
  addOverlapOnly(e.overlap);
  for (int t = 0; t < kPrecisionSteps; ++t)
    if (e.hasCenterDist && e.centerDistPx <= t) ++_precisionFrames[t];
  if (e.hasCenterDist) {
    _centerSum += e.centerDistPx;
    ++_centerFrames;
  }
}

void RunAccumulator::addPosition(const float truthMm[3], const float estimateMm[3]) {
  double ss = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = double(estimateMm[a]) - double(truthMm[a]);
    ss += d * d;
  }
  _centerMmSum += std::sqrt(ss);
  _centerZMmSum += std::fabs(double(estimateMm[2]) - double(truthMm[2]));
  ++_centerMmFrames;
}

void RunAccumulator::addOverlapOnly(double overlapValue) {
  ++_frames;
  _overlapSum += overlapValue;
  if (overlapValue > kHitThreshold) ++_hits;
  if (overlapValue > kPascalThreshold) ++_pascals;
  for (int t = 0; t < kSuccessSteps; ++t)
    if (overlapValue > t / double(kSuccessSteps - 1)) ++_successFrames[t];
}

RunFigures RunAccumulator::figures() const {
  RunFigures f;
  f.frames = _frames;
  if (_frames > 0) {
    f.overlapPct = 100.0 * _overlapSum / _frames;
    f.hitPct = 100.0 * _hits / _frames;
    f.pascalPct = 100.0 * _pascals / _frames;
    for (int t = 0; t < kSuccessSteps; ++t) f.success[t] = double(_successFrames[t]) / _frames;
    for (int t = 0; t < kPrecisionSteps; ++t)
      f.precision[t] = double(_precisionFrames[t]) / _frames;
  }
  f.centerFrames = _centerFrames;
  f.centerPx =
      _centerFrames > 0 ? _centerSum / _centerFrames : std::numeric_limits<double>::quiet_NaN();
  f.centerMmFrames = _centerMmFrames;
  f.centerMm = _centerMmFrames > 0 ? _centerMmSum / _centerMmFrames
                                   : std::numeric_limits<double>::quiet_NaN();
  f.centerZMm = _centerMmFrames > 0 ? _centerZMmSum / _centerMmFrames
                                    : std::numeric_limits<double>::quiet_NaN();
  return f;
}

namespace {
// The curves' single figures [%], from the mean curves.
void curveFigures(Figures* f) {
  double sum = 0.0;
  for (const double v : f->success) sum += v;
  f->auc = 100.0 * sum / kSuccessSteps;
  f->precision20 = 100.0 * f->precision[kPrecisionAtPx];
}
}  // namespace

double Figures::overlapSpread() const {
  const size_t n = runOverlap.size();
  if (n < 2) return 0.0;
  double mean = 0.0;
  for (const double v : runOverlap) mean += v;
  mean /= double(n);
  double ss = 0.0;
  for (const double v : runOverlap) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / double(n - 1));
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  const double lower =
      *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

Figures aggregateRuns(const std::vector<RunFigures>& runs, const std::vector<double>& frameTimesUs,
                      const std::vector<double>& allocsPerRun) {
  Figures f;
  f.centerPx = f.centerMm = f.centerZMm = std::numeric_limits<double>::quiet_NaN();
  if (runs.empty()) return f;
  double centerSum = 0.0, centerMmSum = 0.0, centerZMmSum = 0.0;
  int centerRuns = 0, centerMmRuns = 0;
  for (const RunFigures& r : runs) {
    f.overlap += r.overlapPct;
    f.runOverlap.push_back(r.overlapPct);
    for (int t = 0; t < kSuccessSteps; ++t) f.success[t] += r.success[t] / double(runs.size());
    for (int t = 0; t < kPrecisionSteps; ++t)
      f.precision[t] += r.precision[t] / double(runs.size());
    f.hit += r.hitPct;
    f.pascal += r.pascalPct;
    if (r.centerFrames > 0) {
      centerSum += r.centerPx;
      ++centerRuns;
    }
    if (r.frames > 0) f.centerPct += 100.0 * r.centerFrames / r.frames;
    if (r.centerMmFrames > 0) {
      centerMmSum += r.centerMm;
      centerZMmSum += r.centerZMm;
      ++centerMmRuns;
    }
  }
  const double n = static_cast<double>(runs.size());
  f.frames = runs.front().frames;
  f.overlap /= n;
  f.hit /= n;
  f.pascal /= n;
  f.centerPct /= n;
  curveFigures(&f);
  if (centerRuns > 0) f.centerPx = centerSum / centerRuns;
  if (centerMmRuns > 0) {
    f.centerMm = centerMmSum / centerMmRuns;
    f.centerZMm = centerZMmSum / centerMmRuns;
  }
  if (!frameTimesUs.empty()) {
    double sum = 0.0;
    for (double t : frameTimesUs) sum += t;
    f.msMean = sum / static_cast<double>(frameTimesUs.size()) / 1000.0;
    f.msMedian = median(frameTimesUs) / 1000.0;
  }
  if (!allocsPerRun.empty()) {
    double sum = 0.0;
    for (double a : allocsPerRun) sum += a;
    f.allocs = sum / static_cast<double>(allocsPerRun.size());
  }
  return f;
}

Figures averageFigures(const std::vector<Figures>& sequences) {
  Figures a;
  a.centerPx = a.centerMm = a.centerZMm = std::numeric_limits<double>::quiet_NaN();
  if (sequences.empty()) return a;
  double centerSum = 0.0, centerMmSum = 0.0, centerZMmSum = 0.0;
  int centerSeqs = 0, centerMmSeqs = 0;
  bool allStages = true;
  // Seed k's average needs every sequence to have a k-th run.
  size_t runs = sequences.front().runOverlap.size();
  for (const Figures& s : sequences) runs = std::min(runs, s.runOverlap.size());
  a.runOverlap.assign(runs, 0.0);
  for (const Figures& s : sequences) {
    for (size_t k = 0; k < runs; ++k) a.runOverlap[k] += s.runOverlap[k] / double(sequences.size());
    for (int t = 0; t < kSuccessSteps; ++t) a.success[t] += s.success[t] / double(sequences.size());
    for (int t = 0; t < kPrecisionSteps; ++t)
      a.precision[t] += s.precision[t] / double(sequences.size());
    a.frames += s.frames;
    a.overlap += s.overlap;
    a.hit += s.hit;
    a.pascal += s.pascal;
    a.centerPct += s.centerPct;
    a.msMedian += s.msMedian;
    a.msMean += s.msMean;
    a.allocs += s.allocs;
    for (int i = 0; i < 5; ++i) a.stageMs[i] += s.stageMs[i];
    allStages = allStages && s.hasStages;
    if (!std::isnan(s.centerPx)) {
      centerSum += s.centerPx;
      ++centerSeqs;
    }
    if (!std::isnan(s.centerMm)) {
      centerMmSum += s.centerMm;
      centerZMmSum += s.centerZMm;
      ++centerMmSeqs;
    }
  }
  const double n = static_cast<double>(sequences.size());
  a.overlap /= n;
  a.hit /= n;
  a.pascal /= n;
  a.centerPct /= n;
  a.msMedian /= n;
  a.msMean /= n;
  a.allocs /= n;
  for (double& s : a.stageMs) s /= n;
  a.hasStages = allStages;
  curveFigures(&a);
  if (centerSeqs > 0) a.centerPx = centerSum / centerSeqs;
  if (centerMmSeqs > 0) {
    a.centerMm = centerMmSum / centerMmSeqs;
    a.centerZMm = centerZMmSum / centerMmSeqs;
  }
  return a;
}

}  // namespace cuetrack::bench
