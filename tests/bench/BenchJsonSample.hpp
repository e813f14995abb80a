// Bench results with the values a JSON writer gets wrong: rounding at the last written
// decimal, negative zero, NaN and infinities, tiny and large numbers, names with quotes,
// backslashes, control characters and UTF-8, a sequence not run, an entry with none.
// data/bench-json-v1.json is what the hand-written writer (before nlohmann-json) made of
// them: test_bench_json checks that today's file holds the very same values.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "Results.hpp"

namespace cuetrack::bench::sample {

inline Figures figures(double base) {
  Figures f;
  f.frames = 404;
  f.overlap = base + 0.12345678;
  f.hit = 99.0104999;
  f.pascal = 95.5455;   // at the third decimal's rounding edge
  f.centerPx = 4.3215;  // likewise
  f.centerPct = 74.0;
  f.centerMm = 12.46;
  f.centerZMm = 3.25;
  f.msMedian = 1.23456789;
  f.msMean = 12345.67891;
  f.allocs = 0.05;
  f.auc = 78.12349;
  f.precision20 = 97.0300001;
  for (int t = 0; t < kSuccessSteps; ++t) f.success[t] = 1.0 - t / 20.0 + 0.00004 * t;
  for (int t = 0; t < kPrecisionSteps; ++t) f.precision[t] = t / 50.0 - 0.000049;
  f.runOverlap = {base + 0.5125, base - 0.2, base, base + 0.0004999, -0.0};
  return f;
}

inline std::vector<EntryResult> entries() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EntryResult a;
  a.tracker = "cuetrack";
  a.config = "best";
  a.runs = 5;
  SequenceResult s1;
  s1.name = "Vid_C_juice";
  s1.ran = true;
  s1.figures = figures(80.0);
  s1.skippedFrames = 3;
  SequenceResult s2;
  s2.name = "seq \"two\" \\ tab\there\nnew \x01\x1f caf\xc3\xa9";
  s2.ran = true;
  s2.figures = figures(0.0);
  s2.figures.centerPx = nan;
  s2.figures.centerMm = inf;
  s2.figures.centerZMm = -inf;
  s2.figures.msMedian = 0.00004;
  s2.figures.allocs = -0.04;
  s2.figures.overlap = 1e-7;
  s2.figures.runOverlap = {};
  SequenceResult s3;
  s3.name = "broken";
  s3.ran = false;
  s3.error = "cannot run: no colour";
  s3.figures = figures(50.0);  // not written: a sequence not run has nulls
  a.sequences = {s1, s2, s3};

  EntryResult b;
  b.tracker = "opencv-kcf";
  b.config = "default";
  b.runs = 1;
  SequenceResult k1 = s1;
  k1.figures = figures(42.0);
  k1.figures.runOverlap = {42.5};
  k1.skippedFrames = 0;
  SequenceResult k2 = s3;
  b.sequences = {k1, k2};

  EntryResult c;  // ran on nothing: the average is all nulls
  c.tracker = "opencv-mosse";
  c.config = "default";
  c.runs = 2;
  c.sequences = {s3};
  return {a, b, c};
}

}  // namespace cuetrack::bench::sample
