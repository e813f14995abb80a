// Particle filter parts: motion model statistics, depth correction onto a known
// surface, projection, and resampling.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/filter/ParticleFilter.hpp"

using namespace cuetrack;

TEST_CASE("3D motion: velocity noise variance grows as sigma^2 dt", "[core][motion]") {
  MotionModel3d m;
  m.velocityNoiseMm2PerS2 = 550.f;
  m.positionNoise = 0.f;  // isolate the paper's term
  Rng rng(3);
  const float dt = 0.1f;
  double s[3] = {0, 0, 0}, s2[3] = {0, 0, 0}, px = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    Particle q;
    q.p[2] = 2000.f;
    q.v[0] = 100.f;  // mm/s
    q.size[0] = 200.f;
    q.size[1] = 300.f;
    m.predict(q, rng, dt, 1.f);
    px += q.p[0];
    for (int a = 0; a < 3; ++a) {
      const double dv = q.v[a] - (a == 0 ? 100.0 : 0.0);
      s[a] += dv;
      s2[a] += dv * dv;
    }
    REQUIRE(q.size[0] == 200.f);  // fixed cylinder unless adaptation is on
  }
  REQUIRE(px / n == Approx(10.0).margin(0.05));  // r' = r + v dt
  for (int a = 0; a < 3; ++a) {
    REQUIRE(s[a] / n == Approx(0.0).margin(0.2));
    REQUIRE(s2[a] / n == Approx(550.0 * dt).epsilon(0.04));
  }
}

TEST_CASE("2D motion: unbiased position noise proportional to window size", "[core][motion]") {
  MotionModel2d m;
  Rng rng(9);
  const int n = 40000;
  double s = 0, s2 = 0, ls = 0;
  for (int i = 0; i < n; ++i) {
    Particle q;
    q.p[0] = 100.f;
    q.size[0] = q.size[1] = 50.f;
    m.predict(q, rng, 1.f);
    s += q.p[0] - 100.0;
    s2 += (q.p[0] - 100.0) * (q.p[0] - 100.0);
    ls += std::log(q.size[0] * q.size[1] / 2500.0);
  }
  const double side = 50.0;
  const double expected =
      side * side * (m.velocityNoise * m.velocityNoise + m.positionNoise * m.positionNoise);
  REQUIRE(s / n == Approx(0.0).margin(0.05));
  REQUIRE(s2 / n == Approx(expected).epsilon(0.04));
  REQUIRE(ls / n == Approx(0.0).margin(0.002));  // no scale drift
}

TEST_CASE("2D motion: over dropped frames a particle coasts on its velocity", "[core][motion]") {
  MotionModel2d m;
  m.positionNoise = m.velocityNoise = m.scaleNoise = m.aspectNoise = 0.f;
  for (int frames = 1; frames <= 3; ++frames) {
    Rng rng(1);
    Particle q;
    q.p[0] = 100.f;
    q.v[0] = 4.f;  // px per frame
    q.size[0] = q.size[1] = 50.f;
    m.predict(q, rng, 1.f, frames);
    REQUIRE(q.v[0] == Approx(4.f * m.velocityDecay));  // decayed once: per given frame
    REQUIRE(q.p[0] == Approx(100.f + static_cast<float>(frames) * q.v[0]));
  }
}

TEST_CASE("2D jump: the displacement becomes velocity, spread as scale x noise", "[core][motion]") {
  MotionModel2d m;
  Rng rng(5);
  const int n = 40000;
  double s2 = 0;
  for (int i = 0; i < n; ++i) {
    Particle q;
    q.p[0] = 100.f;
    q.p[1] = 80.f;
    q.v[0] = 2.f;
    q.size[0] = 40.f;
    q.size[1] = 90.f;  // side sqrt(40 x 90) = 60
    m.jump(q, rng, 3.f);
    REQUIRE(q.v[0] - 2.f == Approx(q.p[0] - 100.f).margin(1e-4));
    REQUIRE(q.v[1] == Approx(q.p[1] - 80.f).margin(1e-4));
    REQUIRE(q.size[0] == 40.f);
    s2 += (q.p[0] - 100.0) * (q.p[0] - 100.0);
  }
  const double sd = 3.0 * m.positionNoise * 60.0;
  REQUIRE(s2 / n == Approx(sd * sd).epsilon(0.04));
}

TEST_CASE("3D jump: sideways only, the displacement over dt becomes velocity", "[core][motion]") {
  MotionModel3d m;
  Rng rng(8);
  const float dt = 0.1f;  // 10 fps
  const int n = 40000;
  double s2 = 0;
  for (int i = 0; i < n; ++i) {
    Particle q;
    q.p[0] = 10.f;
    q.p[2] = 2000.f;
    q.v[1] = 50.f;
    q.size[0] = 200.f;
    q.size[1] = 300.f;
    m.jump(q, rng, dt, 3.f);
    REQUIRE(q.p[2] == 2000.f);  // the depth correction sets z
    REQUIRE(q.v[0] * dt == Approx(q.p[0] - 10.f).margin(1e-3));
    REQUIRE((q.v[1] - 50.f) * dt == Approx(q.p[1]).margin(1e-3));
    REQUIRE(q.v[2] == 0.f);
    s2 += (q.p[0] - 10.0) * (q.p[0] - 10.0);
  }
  // 3 x positionNoise x D per sqrt(frame of 1/30 s)
  const double sd = 3.0 * m.positionNoise * 200.0 * std::sqrt(dt * 30.0);
  REQUIRE(s2 / n == Approx(sd * sd).epsilon(0.04));
}

TEST_CASE("frame period: a steady stream is one frame a step, a gap counts its frames",
          "[core][motion]") {
  FramePeriod p;
  // 30 fps with +-1 ms jitter, then one and two dropped frames, then a long stall.
  REQUIRE(p.framesElapsed(33000) == 1);  // no history yet
  for (int i = 0; i < 12; ++i) REQUIRE(p.framesElapsed(i % 2 ? 34000 : 32500) == 1);
  REQUIRE(p.framesElapsed(66700) == 2);
  REQUIRE(p.framesElapsed(33300) == 1);
  REQUIRE(p.framesElapsed(100000) == 3);
  REQUIRE(p.framesElapsed(900000) == FramePeriod::kMaxGap);
  // The median ignores isolated gaps: a stream at any rate is 1 a step.
  FramePeriod slow;
  for (int i = 0; i < 20; ++i)
    REQUIRE(slow.framesElapsed(i % 5 == 4 ? 200000 : 100000) == (i % 5 == 4 && i > 0 ? 2 : 1));
  // clear() forgets the old rate.
  slow.clear();
  REQUIRE(slow.framesElapsed(33000) == 1);
  REQUIRE(slow.framesElapsed(33000) == 1);
}

namespace {
constexpr int W = 160, H = 120;
uint16_t depth[W * H];
Rgb8 rgb[W * H];
IntegralChannels channels;
}  // namespace

TEST_CASE("depth correction puts particles onto a known plane", "[core][depth]") {
  // A fronto-parallel wall at 1800 mm, with a few holes.
  for (int i = 0; i < W * H; ++i) depth[i] = (i % 7 == 0) ? 0 : 1800;
  Frame f;
  f.rgb = RgbView{rgb, W, H, W};
  f.depthMm = DepthView{depth, W, H, W};
  f.intrinsics = CameraIntrinsics{130.f, 130.f, 80.f, 60.f};
  channels.compute(f, PixelRect{0, 0, W, H}, true);
  Rng rng(4);
  for (int trial = 0; trial < 200; ++trial) {
    Particle q;
    q.size[0] = 150.f;  // D
    q.size[1] = 300.f;  // H
    q.p[2] = rng.uniform(900.f, 3500.f);
    q.p[0] = rng.uniform(-0.3f, 0.3f) * q.p[2];
    q.p[1] = rng.uniform(-0.3f, 0.3f) * q.p[2];
    const Particle before = q;
    const float dt = 1.f / 30.f;
    const Box b0 = projectCylinder(before, f.intrinsics);
    REQUIRE(correctDepth(q, channels, f.intrinsics, dt, W, H));
    // Front surface on the wall: centre at wall + D/2.
    REQUIRE(q.p[2] == Approx(1800.f + 75.f).epsilon(1e-5));
    // Along the viewing ray: the projected centre does not move.
    const Box b1 = projectCylinder(q, f.intrinsics);
    REQUIRE(b1.x + 0.5f * b1.w == Approx(b0.x + 0.5f * b0.w).margin(1e-2));
    REQUIRE(b1.y + 0.5f * b1.h == Approx(b0.y + 0.5f * b0.h).margin(1e-2));
    // Velocity corrected by the move / dt.
    for (int a = 0; a < 3; ++a) REQUIRE(q.v[a] == Approx((q.p[a] - before.p[a]) / dt).margin(0.5f));
  }
  // A repeated frame (200 us later) moves the particle but leaves its velocity: move / dt
  // would otherwise fling it at metres per second.
  {
    Particle q;
    q.size[0] = 150.f;
    q.size[1] = 300.f;
    q.p[2] = 2500.f;
    q.v[0] = 10.f;
    REQUIRE(correctDepth(q, channels, f.intrinsics, 2e-4f, W, H));
    REQUIRE(q.p[2] == Approx(1875.f).epsilon(1e-5));
    REQUIRE(q.v[0] == 10.f);
    REQUIRE(q.v[1] == 0.f);
    REQUIRE(q.v[2] == 0.f);
  }
  // No valid depth: untouched.
  for (int i = 0; i < W * H; ++i) depth[i] = 0;
  channels.compute(f, PixelRect{0, 0, W, H}, true);
  Particle q;
  q.p[2] = 2000.f;
  q.size[0] = 150.f;
  q.size[1] = 300.f;
  REQUIRE_FALSE(correctDepth(q, channels, f.intrinsics, 0.033f, W, H));
  REQUIRE(q.p[2] == 2000.f);
}

TEST_CASE("the valid-depth fraction of a rectangle counts its readings", "[core][depth]") {
  // Left half holes, right half 1500 mm; tables over the right three quarters only.
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) depth[v * W + u] = u < W / 2 ? 0 : 1500;
  Frame f;
  f.rgb = RgbView{rgb, W, H, W};
  f.depthMm = DepthView{depth, W, H, W};
  channels.compute(f, PixelRect{W / 4, 0, W, H}, true);
  CHECK(channels.validDepthFraction(PixelRect{W / 2, 10, W, 20}) == 1.f);
  CHECK(channels.validDepthFraction(PixelRect{W / 4, 10, W / 2, 20}) == 0.f);
  CHECK(channels.validDepthFraction(PixelRect{W / 2 - 10, 10, W / 2 + 30, 20}) == 0.75f);
  // Outside the tables counts as no reading; an empty rectangle is 0, not a division by 0.
  CHECK(channels.validDepthFraction(PixelRect{0, 0, W / 4, H}) == 0.f);
  CHECK(channels.validDepthFraction(PixelRect{0, 10, W / 2 + 40, 20}) ==
        Approx(40.f / (W / 2 + 40)));
  CHECK(channels.validDepthFraction(PixelRect{30, 30, 30, 40}) == 0.f);
  // Without depth every rectangle has none.
  f.depthMm = DepthView{};
  channels.compute(f, PixelRect{0, 0, W, H}, true);
  CHECK(channels.validDepthFraction(PixelRect{W / 2, 10, W, 20}) == 0.f);
}

TEST_CASE("the cylinder projects to the right rectangle", "[core][depth]") {
  Particle q;
  q.p[0] = 100.f;
  q.p[1] = -50.f;
  q.p[2] = 2000.f;
  q.size[0] = 200.f;
  q.size[1] = 400.f;
  const CameraIntrinsics k{500.f, 520.f, 320.f, 240.f};
  const Box b = projectCylinder(q, k);
  REQUIRE(b.w == Approx(50.f));
  REQUIRE(b.h == Approx(104.f));
  REQUIRE(b.x + 0.5f * b.w == Approx(345.f));
  REQUIRE(b.y + 0.5f * b.h == Approx(227.f));
  q.p[2] = -10.f;
  REQUIRE(projectCylinder(q, k).empty());
}

TEST_CASE("systematic resampling keeps particles in proportion to weight", "[core][filter]") {
  static ParticleFilter pf;
  pf.setSize(2000);
  Rng rng(2);
  double mass[4] = {0, 0, 0, 0};
  for (int i = 0; i < 2000; ++i) {
    const int k = static_cast<int>(rng.below(4));
    pf[i].p[0] = static_cast<float>(k);
    pf.weights()[i] = static_cast<float>(k);  // weights 0, 1, 2, 3
    mass[k] += k;
  }
  const double total = mass[1] + mass[2] + mass[3];
  pf.resample(rng);
  int count[4] = {0, 0, 0, 0};
  for (int i = 0; i < 2000; ++i) ++count[static_cast<int>(pf[i].p[0])];
  REQUIRE(count[0] == 0);
  for (int k = 1; k < 4; ++k) REQUIRE(count[k] == Approx(2000.0 * mass[k] / total).epsilon(0.03));
  REQUIRE(pf.weights()[0] == 1.f);
  // A single heavy particle takes (almost) everything.
  for (int i = 0; i < 2000; ++i) {
    pf[i].p[0] = static_cast<float>(i);
    pf.weights()[i] = i == 777 ? 1e6f : 1e-6f;
  }
  pf.resample(rng);
  int heavy = 0;
  for (int i = 0; i < 2000; ++i) heavy += pf[i].p[0] == 777.f ? 1 : 0;
  REQUIRE(heavy >= 1999);
}

TEST_CASE("the weighted mean, of all particles or of a chosen subset", "[core][filter]") {
  static ParticleFilter pf;
  pf.setSize(6);
  // Two clusters: at x 10 (weights 1, 1, 2) and at x 100 (weights 3, 1, 0).
  const float xs[6] = {10.f, 10.f, 10.f, 100.f, 100.f, 100.f};
  const float ws[6] = {1.f, 1.f, 2.f, 3.f, 1.f, 0.f};
  for (int i = 0; i < 6; ++i) {
    pf[i] = Particle{};
    pf[i].p[0] = xs[i];
    pf[i].size[0] = xs[i] * 0.5f;
    pf.weights()[i] = ws[i];
  }
  REQUIRE(pf.argmaxWeight() == 3);
  // All: (40 + 400) / 8 = 55, between the clusters.
  CHECK(pf.weightedMean().p[0] == Approx(55.f));
  CHECK(pf.weightedMean().size[0] == Approx(27.5f));
  const uint8_t right[6] = {0, 0, 0, 1, 1, 1};
  CHECK(pf.weightedMean(right).p[0] == Approx(100.f));
  const uint8_t left[6] = {1, 1, 1, 0, 0, 0};
  CHECK(pf.weightedMean(left).p[0] == Approx(10.f));
  // Nothing of weight included: particle 0, not a division by zero.
  const uint8_t zero[6] = {0, 0, 0, 0, 0, 1};
  CHECK(pf.weightedMean(zero).p[0] == 10.f);
}

TEST_CASE("weigh: the best score weighs 1, the cue's map shifts the weights; concentration",
          "[core][particles]") {
  static ParticleFilter f;  // large: static storage
  f.setSize(3);
  const float scores[3] = {0.5f, 0.2f, 0.5f};
  f.weigh(scores, Span<const float>{});  // the cue did not answer
  CHECK(f.weights()[0] == 1.f);          // exp(0)
  CHECK(f.weights()[1] < f.weights()[0]);
  CHECK(f.weights()[2] == f.weights()[0]);
  const float cue[3] = {0.9f, 0.9f, 0.1f};  // the cue prefers particles 0 and 1
  f.weigh(scores, cue);
  CHECK(f.weights()[0] == 1.f);
  CHECK(f.weights()[2] < f.weights()[0]);
  // Concentration: the weighted mean overlap with the estimate.
  const Box e{0.f, 0.f, 10.f, 10.f};
  const Box on[3] = {e, e, e};
  CHECK(f.concentration(on, e) == Approx(1.f));
  const Box off[3] = {e, e, Box{50.f, 50.f, 10.f, 10.f}};
  const float w2 = f.weights()[2];
  CHECK(f.concentration(off, e) ==
        Approx((f.weights()[0] + f.weights()[1]) / (f.weights()[0] + f.weights()[1] + w2)));
  f.forgetVelocities();
  CHECK(f[0].v.isZero());
}
