// The benchmark's metrics on hand-computed cases, empty boxes included.
#include <catch2/catch.hpp>
#include <cmath>

#include "Metrics.hpp"

using namespace cuetrack;
using namespace cuetrack::bench;

TEST_CASE("overlap is intersection over union, hand-computed") {
  // 10x10 at (0,0) and 10x10 at (5,0): intersection 50, union 150.
  const FrameEval e = evaluateFrame(Box{0, 0, 10, 10}, Box{5, 0, 10, 10});
  CHECK(e.overlap == Approx(1.0 / 3.0));
  REQUIRE(e.hasCenterDist);
  CHECK(e.centerDistPx == Approx(5.0));
  // Contained box: 4x4 inside 8x8 -> 16 / 64.
  CHECK(evaluateFrame(Box{0, 0, 8, 8}, Box{2, 2, 4, 4}).overlap == Approx(0.25));
  // Identical boxes.
  CHECK(evaluateFrame(Box{3, 4, 5, 6}, Box{3, 4, 5, 6}).overlap == Approx(1.0));
  // Disjoint: overlap 0 but a centre distance (3-4-5 triangle of centres).
  const FrameEval d = evaluateFrame(Box{0, 0, 2, 2}, Box{30, 40, 2, 2});
  CHECK(d.overlap == 0.0);
  REQUIRE(d.hasCenterDist);
  CHECK(d.centerDistPx == Approx(50.0));
}

TEST_CASE("empty boxes: a missed target scores 0, a target reported absent when absent 1") {
  const Box gt{10, 10, 20, 20};
  const FrameEval noPrediction = evaluateFrame(gt, Box{});
  CHECK(noPrediction.overlap == 0.0);
  CHECK_FALSE(noPrediction.hasCenterDist);
  // The target is not visible: a box reported is wrong ...
  const FrameEval noTarget = evaluateFrame(Box{0, 0, 0, 0}, gt);
  CHECK(noTarget.overlap == 0.0);
  CHECK_FALSE(noTarget.hasCenterDist);
  // Zero width alone is empty too.
  CHECK(evaluateFrame(Box{10, 10, 0, 20}, gt).overlap == 0.0);
  // ... no box, or a box flagged as hidden behind something, is right.
  CHECK(evaluateFrame(Box{}, Box{}).overlap == 1.0);
  CHECK(evaluateFrame(Box{}, gt, true).overlap == 1.0);
  CHECK_FALSE(evaluateFrame(Box{}, gt, true).hasCenterDist);
  // A visible target is scored by its overlap whatever the flag says.
  CHECK(evaluateFrame(gt, Box{10, 10, 20, 10}, true).overlap == Approx(0.5));
}

TEST_CASE("run figures: hit > 1/3, PASCAL > 0.5, a box on an invisible target counts with 0") {
  RunAccumulator acc;
  acc.add(Box{0, 0, 10, 10}, Box{0, 0, 10, 10});  // 1.0: hit, pascal, dist 0
  acc.add(Box{0, 0, 10, 10}, Box{5, 0, 10, 10});  // 1/3 exactly: neither hit nor pascal
  acc.add(Box{0, 0, 10, 10}, Box{0, 0, 10, 5});   // 0.5 exactly: hit, not pascal; dist 2.5
  acc.add(Box{}, Box{0, 0, 10, 10});              // target invisible: counts, 0, no dist
  const RunFigures f = acc.figures();
  CHECK(f.frames == 4);
  CHECK(f.overlapPct == Approx(100.0 * (1.0 + 1.0 / 3.0 + 0.5 + 0.0) / 4.0));
  CHECK(f.hitPct == Approx(25.0 * 2));  // 1.0 and 0.5
  CHECK(f.pascalPct == Approx(25.0));   // only 1.0
  CHECK(f.centerFrames == 3);
  CHECK(f.centerPx == Approx((0.0 + 5.0 + 2.5) / 3.0));
}

TEST_CASE("a run where no frame has both boxes has no centre distance") {
  RunAccumulator acc;
  acc.add(Box{0, 0, 10, 10}, Box{});
  const RunFigures f = acc.figures();
  CHECK(f.frames == 1);
  CHECK(f.overlapPct == 0.0);
  CHECK(f.centerFrames == 0);
  CHECK(std::isnan(f.centerPx));
  CHECK(std::isnan(aggregateRuns({f}, {}, {}).centerPx));
}

TEST_CASE("3D centre error: distance and |z| in mm, hand-computed; none gives NaN") {
  RunAccumulator acc;
  CHECK(std::isnan(acc.figures().centerMm));
  CHECK(std::isnan(acc.figures().centerZMm));
  const float truth[3] = {100.f, -50.f, 2000.f};
  const float a[3] = {103.f, -46.f, 2012.f};  // (3, 4, 12): 13 mm, z 12 mm
  const float b[3] = {100.f, -50.f, 1995.f};  // 5 mm, all of it in z
  acc.addPosition(truth, a);
  acc.addPosition(truth, b);
  const RunFigures f = acc.figures();
  CHECK(f.centerMmFrames == 2);
  CHECK(f.centerMm == Approx(9.0));   // (13 + 5) / 2
  CHECK(f.centerZMm == Approx(8.5));  // (12 + 5) / 2
  CHECK(f.frames == 0);               // overlap frames are counted apart

  // Over runs, a run without 3D positions is left out; over sequences likewise.
  RunFigures none;
  none.centerMm = none.centerZMm = std::nan("");
  const Figures g = aggregateRuns({f, none}, {}, {});
  CHECK(g.centerMm == Approx(9.0));
  CHECK(std::isnan(aggregateRuns({none}, {}, {}).centerMm));
  Figures s2;
  s2.centerMm = s2.centerZMm = std::nan("");
  CHECK(averageFigures({g, s2}).centerMm == Approx(9.0));
  CHECK(averageFigures({g, s2}).centerZMm == Approx(8.5));
  CHECK(std::isnan(averageFigures({s2}).centerMm));
}

TEST_CASE("aggregation over runs: means of run figures, times pooled") {
  RunFigures a, b;
  a.frames = b.frames = 10;
  a.overlapPct = 80;
  b.overlapPct = 60;
  a.hitPct = 100;
  b.hitPct = 90;
  a.pascalPct = 90;
  b.pascalPct = 70;
  a.centerPx = 4;
  a.centerFrames = 10;
  b.centerPx = 0;
  b.centerFrames = 0;  // excluded from the centre mean
  const Figures f = aggregateRuns({a, b}, {1000, 3000, 2000, 10000}, {0, 4});
  CHECK(f.frames == 10);
  CHECK(f.overlap == Approx(70));
  CHECK(f.hit == Approx(95));
  CHECK(f.pascal == Approx(80));
  CHECK(f.centerPx == Approx(4));
  CHECK(f.centerPct == Approx(50));  // run b's 10 frames are all left out of it
  CHECK(f.msMedian == Approx(2.5));  // (2000 + 3000) / 2 us
  CHECK(f.msMean == Approx(4.0));    // 16000 / 4 us
  CHECK(f.allocs == Approx(2.0));
}

TEST_CASE("average over sequences is the macro mean, centre over those that have one") {
  Figures s1, s2;
  s1.frames = 100;
  s2.frames = 50;
  s1.overlap = 90;
  s2.overlap = 70;
  s1.centerPx = 6;
  s2.centerPx = std::nan("");
  s1.centerPct = 100;
  s2.centerPct = 0;
  s1.msMean = 2;
  s2.msMean = 4;
  const Figures a = averageFigures({s1, s2});
  CHECK(a.frames == 150);
  CHECK(a.overlap == Approx(80));
  CHECK(a.centerPx == Approx(6));
  CHECK(a.centerPct == Approx(50));  // so the table can say what dist. leaves out
  CHECK(a.msMean == Approx(3));
  CHECK(std::isnan(averageFigures({}).centerPx));
}

TEST_CASE("median of odd, even and empty sets") {
  CHECK(median({3, 1, 2}) == 2);
  CHECK(median({4, 1, 3, 2}) == Approx(2.5));
  CHECK(median({}) == 0);
}

TEST_CASE("success and precision curves, hand-computed: OTB's thresholds, lost frames miss") {
  RunAccumulator acc;
  const Box gt{0, 0, 10, 10};
  acc.add(gt, gt);                   // overlap 1, distance 0
  acc.add(gt, Box{5, 0, 10, 10});    // overlap 1/3, distance 5
  acc.add(gt, Box{});                // lost: overlap 0, no distance
  acc.add(gt, Box{100, 0, 10, 10});  // overlap 0, distance 100
  const RunFigures r = acc.figures();
  CHECK(r.success[0] == Approx(0.5));   // overlap > 0: two of four
  CHECK(r.success[6] == Approx(0.5));   // > 0.30: 1 and 1/3
  CHECK(r.success[7] == Approx(0.25));  // > 0.35: only the exact box
  CHECK(r.success[20] == Approx(0.0));  // > 1: none
  CHECK(r.precision[0] == Approx(0.25));
  CHECK(r.precision[4] == Approx(0.25));
  CHECK(r.precision[5] == Approx(0.5));   // <= 5 px
  CHECK(r.precision[50] == Approx(0.5));  // 100 px and the lost frame never count
  // AUC is the mean of the 21 points: 0.5 x 7 (0 .. 0.30) + 0.25 x 13 (0.35 .. 0.95) + 0.
  const Figures f = aggregateRuns({r}, {}, {});
  CHECK(f.auc == Approx(100.0 * (0.5 * 7 + 0.25 * 13) / 21));
  CHECK(f.precision20 == Approx(50.0));
}

TEST_CASE("seed spread: the sample s.d. of the per-seed averages over sequences") {
  RunFigures a1, a2, b1, b2;
  a1.overlapPct = 60;
  a2.overlapPct = 70;
  b1.overlapPct = 80;
  b2.overlapPct = 80;
  const Figures a = aggregateRuns({a1, a2}, {}, {});
  const Figures b = aggregateRuns({b1, b2}, {}, {});
  CHECK(a.overlapSpread() == Approx(std::sqrt(50.0)));  // 60, 70
  CHECK(b.overlapSpread() == 0.0);
  const Figures avg = averageFigures({a, b});
  REQUIRE(avg.runOverlap.size() == 2);
  CHECK(avg.runOverlap[0] == Approx(70.0));  // seed 1: (60 + 80) / 2
  CHECK(avg.runOverlap[1] == Approx(75.0));
  CHECK(avg.overlapSpread() == Approx(std::sqrt(12.5)));
  CHECK(aggregateRuns({a1}, {}, {}).overlapSpread() == 0.0);  // one run: no spread
}
