// The beyond-the-paper components the tracker wires, each on its own: the depth guard,
// the occlusion test, fast motion's jumps, the lost search, the peak contrast, and the small
// helpers (the depth median that places a new 3D track, the scan order, the small target's
// padding).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "cuetrack/core/cues/DepthMedian.hpp"
#include "cuetrack/core/filter/FastMotion.hpp"
#include "cuetrack/core/filter/LostSearch.hpp"
#include "cuetrack/core/guards/DepthGuard.hpp"
#include "cuetrack/core/guards/Occlusion.hpp"
#include "cuetrack/core/guards/PeakContrast.hpp"
#include "cuetrack/core/model/ScanOrder.hpp"
#include "cuetrack/core/tracker/WindowPadding.hpp"

using namespace cuetrack;

namespace {
constexpr float kFrameS = 1.f / 30.f;

Particle at2d(float u, float v, float w, float h) {
  Particle q;
  q.p[0] = u;
  q.p[1] = v;
  q.size[0] = w;
  q.size[1] = h;
  return q;
}
}  // namespace

TEST_CASE("DepthGuard: a jump off the confirmed depth either way is flagged",
          "[core][depthguard]") {
  DepthGuard g;
  g.reset(2000.f);
  CHECK_FALSE(g.jumped(2000.f));
  CHECK_FALSE(g.jumped(1600.f));
  CHECK(g.jumped(1400.f));  // under 0.75 x 2000: something passing in front
  CHECK_FALSE(g.jumped(2600.f));
  CHECK(g.jumped(2700.f));  // 0.75 x 2700 > 2000: the background behind
  // Found again further back: the confirmed depth moves there.
  g.confirm(2700.f);
  CHECK_FALSE(g.jumped(2700.f));
  CHECK(g.confirmedMm() == 2700.f);
}

TEST_CASE("DepthGuard: a find far off the confirmed depth is not the target",
          "[core][depthguard]") {
  DepthGuard g;
  g.reset(2000.f);
  // The target may have moved in depth while hidden: a find at 1.6 m or 2.6 m is allowed,
  // one on the floor or a wall at twice the depth, or on a look-alike at 1.4 m, is not.
  CHECK_FALSE(g.implausibleFind(2000.f));
  CHECK_FALSE(g.implausibleFind(1600.f));
  CHECK_FALSE(g.implausibleFind(2600.f));
  CHECK(g.implausibleFind(2700.f));
  CHECK(g.implausibleFind(4000.f));
  CHECK(g.implausibleFind(1400.f));
  CHECK(g.implausibleFind(1000.f));
}

TEST_CASE("Occlusion: the part of a box's valid depth nearer than a bound", "[core][occlusion]") {
  // 100 x 80 px of target at 2000 mm; its left 40 columns covered by a board at 1500 mm,
  // a hole (0) over its top 20 rows.
  std::vector<uint16_t> px(100 * 80, 2000);
  for (int y = 0; y < 80; ++y)
    for (int x = 0; x < 40; ++x) px[y * 100 + x] = 1500;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 100; ++x) px[y * 100 + x] = 0;
  const DepthView depth{px.data(), 100, 80, 100};
  const Box whole{0.f, 0.f, 100.f, 80.f};
  const float below = occlusion::occluderBelowMm(1950.f, 200.f);
  CHECK(below < 1950.f - 100.f - 30.f);  // past the target's own relief and depth noise ...
  CHECK(below > 1600.f);                 // ... and near enough to see a board 450 mm in front
  // Holes are not counted: 40 % of the columns, over the rows that have depth.
  CHECK(occlusion::nearerFraction(depth, whole, below) == Approx(0.4f).margin(0.04f));
  CHECK(occlusion::nearerFraction(depth, Box{50.f, 0.f, 50.f, 80.f}, below) == 0.f);
  CHECK(occlusion::nearerFraction(depth, Box{0.f, 30.f, 30.f, 30.f}, below) == 1.f);
  // All holes, an empty box, a box off the image: nothing seen, nothing covered.
  CHECK(occlusion::nearerFraction(depth, Box{0.f, 0.f, 100.f, 19.f}, below) == 0.f);
  CHECK(occlusion::nearerFraction(depth, Box{}, below) == 0.f);
  CHECK(occlusion::nearerFraction(depth, Box{200.f, 200.f, 10.f, 10.f}, below) == 0.f);
  // A box partly off the image: only its part on the image is read.
  CHECK(occlusion::nearerFraction(depth, Box{-50.f, 30.f, 80.f, 30.f}, below) == 1.f);
}

TEST_CASE("LearntMotion: the slope of the learnt positions, once there are enough",
          "[core][occlusion]") {
  LearntMotion m;
  float v[3];
  // 30 fps, x at 40 mm/s with +-5 mm of alternating noise, y still, z at -100 mm/s.
  auto at = [](int k, float out[3]) {
    out[0] = 100.f + 40.f * static_cast<float>(k) / 30.f + (k % 2 != 0 ? 5.f : -5.f);
    out[1] = 200.f;
    out[2] = 2400.f - 100.f * static_cast<float>(k) / 30.f;
  };
  float p[3];
  for (int k = 0; k < LearntMotion::kMinSamples - 1; ++k) {
    at(k, p);
    m.add(1000000u + static_cast<uint64_t>(k) * 33333u, p);
  }
  CHECK_FALSE(m.velocity(v));  // too few samples: no velocity
  CHECK(v[0] == 0.f);
  for (int k = LearntMotion::kMinSamples - 1; k < 40; ++k) {
    at(k, p);
    m.add(1000000u + static_cast<uint64_t>(k) * 33333u, p);
  }
  REQUIRE(m.velocity(v));
  CHECK(v[0] == Approx(40.f).margin(6.f));  // the noise alone would give +-300 mm/s a frame
  CHECK(v[1] == Approx(0.f).margin(1e-3f));
  CHECK(v[2] == Approx(-100.f).margin(1.f));
  // Time going back (a new recording): started again, too few samples.
  m.add(1000u, p);
  CHECK_FALSE(m.velocity(v));
  // Samples under kMinSpanS apart (a burst of frames): no velocity either.
  m.clear();
  for (int k = 0; k < LearntMotion::kSamples; ++k) m.add(1000000u + static_cast<uint64_t>(k), p);
  CHECK_FALSE(m.velocity(v));
}

TEST_CASE("FastMotion: in 2D every 10th particle jumps after a learnt frame only",
          "[core][fastmotion]") {
  FastMotion fm;
  fm.configure(true);
  fm.start();
  MotionModel2d m;
  Rng rng(1);
  fm.beginFrame(false, kFrameS);
  REQUIRE(fm.jumping());
  double jumped = 0.0;
  for (int i = 0; i < 200; ++i) {
    Particle q = at2d(100.f, 100.f, 40.f, 40.f);
    fm.jump2d(i, q, m, rng);
    const float d = std::hypot(q.p[0] - 100.f, q.p[1] - 100.f);
    if (i % FastMotion::kEvery == 1) {
      jumped += d;
      CHECK(q.v[0] == Approx(q.p[0] - 100.f).margin(1e-4));  // taken into the velocity too
    } else {
      CHECK(d == 0.f);
    }
  }
  // Jumps of 3 x the position noise (0.09 x 40 px): about 3.6 px per axis on average.
  CHECK(jumped / 20.0 > 4.0);
  fm.endFrame(false);  // not learnt: no jumps next frame
  fm.beginFrame(false, kFrameS);
  CHECK_FALSE(fm.jumping());
  FastMotion off;
  off.start();
  off.beginFrame(false, kFrameS);
  CHECK_FALSE(off.jumping());
}

TEST_CASE(
    "FastMotion: in 3D jumps only with frames far apart, and one onto another surface is undone",
    "[core][fastmotion]") {
  FastMotion fm;
  fm.configure(true);
  fm.start();
  fm.beginFrame(true, kFrameS);
  CHECK_FALSE(fm.jumping());  // 30 fps: the AR(1) model keeps up
  fm.beginFrame(true, 0.1f);
  REQUIRE(fm.jumping());
  MotionModel3d m;
  Rng rng(2);
  Particle q;
  q.p[2] = 2000.f;
  q.size[0] = 200.f;
  q.size[1] = 300.f;
  const Particle before = q;
  fm.jump3d(1, q, m, rng, 0.1f);
  CHECK(q.p[0] != before.p[0]);
  Particle near = q;
  near.p[2] = 2100.f;  // 5% deeper: the same surface
  CHECK_FALSE(fm.undoOffSurface(1, near));
  Particle far = q;
  far.p[2] = 2500.f;  // 25% deeper: the wall behind
  REQUIRE(fm.undoOffSurface(1, far));
  CHECK(far.p[0] == before.p[0]);
  CHECK(far.p[2] == before.p[2]);
  Particle other = q;
  other.p[2] = 2500.f;
  CHECK_FALSE(fm.undoOffSurface(2, other));  // not a jumper
}

TEST_CASE("FastMotion: dropped frames are counted from the timestamps (2D)", "[core][fastmotion]") {
  FastMotion fm;
  fm.configure(true);
  fm.start();
  uint64_t t = 1000000;
  for (int i = 0; i < 5; ++i, t += 33333) CHECK(fm.framesElapsed(false, t, t + 33333) == 1);
  CHECK(fm.framesElapsed(false, t, t + 66666) == 2);
  CHECK(fm.framesElapsed(true, t, t + 66666) == 1);  // 3D: the AR(1) model takes dt
  FastMotion off;
  off.start();
  CHECK(off.framesElapsed(false, t, t + 100000) == 1);
}

TEST_CASE("LostSearch: fresh draws, half anywhere, half around the last estimate",
          "[core][lostsearch]") {
  SearchView view;
  view.imageW = 640;
  view.imageH = 480;
  const Particle last = at2d(320.f, 240.f, 40.f, 40.f);
  Rng rng(5);
  int nearCount = 0, wideFar = 0;
  for (int i = 0; i < 400; i += LostSearch::kEvery) {
    REQUIRE(LostSearch::drawsAnew(i));
    const Particle q = LostSearch::draw(i, last, 0, view, rng);
    CHECK(q.v[0] == 0.f);
    CHECK(q.p[0] >= 0.f);
    CHECK(q.p[0] <= 640.f);
    const float d = std::hypot(q.p[0] - 320.f, q.p[1] - 240.f);
    if ((i / LostSearch::kEvery) % 2 == 0)
      wideFar += d > 100.f ? 1 : 0;
    else
      nearCount += d < 80.f ? 1 : 0;  // radius 0.5 x 40 px: within 4 sigma
  }
  CHECK_FALSE(LostSearch::drawsAnew(1));
  CHECK(nearCount == 100);
  CHECK(wideFar > 60);  // most of the image is over 100 px away
}

TEST_CASE("LostSearch: a 3D draw keeps the depth and lands on a ray inside the image",
          "[core][lostsearch]") {
  SearchView view;
  view.is3d = true;
  view.k = kKinectV1Intrinsics;
  view.imageW = 640;
  view.imageH = 480;
  Particle last;
  last.p[2] = 2500.f;
  last.size[0] = 200.f;
  last.size[1] = 400.f;
  Rng rng(6);
  for (int i = 0; i < 40; i += LostSearch::kEvery) {
    const Particle q = LostSearch::draw(i, last, 3, view, rng);
    CHECK(q.p[2] == 2500.f);
    const Box b = view.window(q);
    const float u = b.x + 0.5f * b.w, v = b.y + 0.5f * b.h;
    CHECK(u == Approx(std::min(640.f, std::max(0.f, u))).margin(0.01f));
    CHECK(v >= -0.01f);
    CHECK(v <= 480.01f);
  }
}

TEST_CASE("LostSearch: windows mostly outside the image are not scored", "[core][lostsearch]") {
  CHECK(insideEnough(Box{10.f, 10.f, 50.f, 50.f}, 640, 480));
  CHECK(insideEnough(Box{-5.f, 10.f, 50.f, 50.f}, 640, 480));         // 90% inside
  CHECK_FALSE(insideEnough(Box{-25.f, 10.f, 50.f, 50.f}, 640, 480));  // half
}

TEST_CASE("DepthMedian: the median of the valid depth inside the box, to 10 mm",
          "[core][depthmedian]") {
  std::vector<uint16_t> px(100 * 100, 0);
  for (int y = 10; y < 30; ++y)
    for (int x = 10; x < 30; ++x) px[y * 100 + x] = (x < 25) ? 1503 : 3000;  // 300 near, 100 far
  const DepthView d{px.data(), 100, 100, 100};
  static DepthMedian m;
  float z = 0.f;
  REQUIRE(m.of(d, Box{0.f, 0.f, 50.f, 50.f}, &z));  // holes (0) do not count
  CHECK(z == 1505.f);
  CHECK_FALSE(m.of(d, Box{50.f, 50.f, 40.f, 40.f}, &z));  // no valid pixel
}

TEST_CASE("ScanOrder: windows by 8 px row band, stable within a band", "[core][scanorder]") {
  const Box boxes[5] = {{0.f, 40.f, 8.f, 8.f},
                        {0.f, 3.f, 8.f, 8.f},
                        {0.f, 17.f, 8.f, 8.f},
                        {0.f, 1.f, 8.f, 8.f},
                        {0.f, -30.f, 8.f, 8.f}};
  static ScanOrder s;
  const uint16_t* order = s.sort(Span<const Box>(boxes, 5), 0);
  CHECK(order[0] == 1);  // band 0: 1, 3, 4 (above the ROI counts as band 0), in index order
  CHECK(order[1] == 3);
  CHECK(order[2] == 4);
  CHECK(order[3] == 2);  // band 2
  CHECK(order[4] == 0);  // band 5
}

TEST_CASE("WindowPadding: a small target's window is padded about its centre, and back",
          "[core][padding]") {
  const Box big{10.f, 20.f, 30.f, 40.f};
  const WindowPadding none = WindowPadding::forTarget(big);
  CHECK(none.toWindow(big).w == big.w);  // 16 px and over: the box itself
  CHECK(none.toTarget(big).x == big.x);
  const Box tiny{100.f, 50.f, 6.f, 8.f};
  const WindowPadding p = WindowPadding::forTarget(tiny);
  const Box w = p.toWindow(tiny);
  CHECK(w.w == Approx(tuning::kMinTrackedSidePx));
  CHECK(w.h == Approx(tuning::kMinTrackedSidePx));
  CHECK(w.x + 0.5f * w.w == Approx(103.f));  // same centre
  CHECK(w.y + 0.5f * w.h == Approx(54.f));
  const Box back = p.toTarget(Box{w.x + 4.f, w.y, w.w, w.h});  // the window moved 4 px
  CHECK(back.x == Approx(104.f));
  CHECK(back.w == Approx(6.f));
  CHECK(back.h == Approx(8.f));
}

TEST_CASE("PeakContrast::around scores the ring and takes the mean off the estimate's score",
          "[core][peakcontrast]") {
  int calls = 0;
  const float c = PeakContrast::around(Box{100, 100, 40, 20}, 640, 480, 0.8f, [&](const Box& b) {
    ++calls;
    return b.x < 100.f ? 0.4f : 0.f;  // the window on the left scores 0.4
  });
  CHECK(calls == 4);
  CHECK(c == Approx(0.8f - 0.1f));
  // A window as large as the image has no ring: taken to stand out.
  CHECK(PeakContrast::around(Box{0, 0, 640, 480}, 640, 480, 0.f, [](const Box&) { return 1.f; }) ==
        PeakContrast::kNoRing);
}

TEST_CASE("PeakContrast: the ring is the four windows one side away inside the image",
          "[core][components]") {
  Box ring[PeakContrast::kRing];
  // In the middle: all four, each the estimate's size, touching it.
  REQUIRE(PeakContrast::ring(Box{100, 100, 40, 20}, 640, 480, ring) == 4);
  CHECK(ring[0].x == 60.f);
  CHECK(ring[1].x == 140.f);
  CHECK(ring[2].y == 80.f);
  CHECK(ring[3].y == 120.f);
  for (const Box& b : ring) {
    CHECK(b.w == 40.f);
    CHECK(b.h == 20.f);
  }
  // In the top-left corner: only right and below.
  REQUIRE(PeakContrast::ring(Box{0, 0, 40, 20}, 640, 480, ring) == 2);
  CHECK(ring[0].x == 40.f);
  CHECK(ring[1].y == 20.f);
  // As large as the image, or empty: none.
  CHECK(PeakContrast::ring(Box{0, 0, 640, 480}, 640, 480, ring) == 0);
  CHECK(PeakContrast::ring(Box{}, 640, 480, ring) == 0);
}

TEST_CASE("PeakContrast: a peak stands out, a plateau does not", "[core][components]") {
  const float background[4] = {-0.8f, -0.6f, -0.9f, -0.7f};
  const float plateau[4] = {0.05f, -0.02f, 0.01f, 0.f};
  CHECK(PeakContrast::of(0.6f, Span<const float>(background, 4)) == Approx(1.35f));
  CHECK_FALSE(PeakContrast::flat(PeakContrast::of(0.6f, Span<const float>(background, 4))));
  CHECK(
      PeakContrast::flat(PeakContrast::of(0.02f, Span<const float>(plateau, 4))));  // a plain wall
  // A look-alike beside the target on one side only still leaves it standing out.
  const float oneTwin[4] = {0.6f, -0.8f, -0.8f, -0.8f};
  CHECK_FALSE(PeakContrast::flat(PeakContrast::of(0.6f, Span<const float>(oneTwin, 4))));
  // Nothing to compare with: taken to stand out.
  CHECK_FALSE(PeakContrast::flat(PeakContrast::of(0.f, Span<const float>(background, 0))));
}
