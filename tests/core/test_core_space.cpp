// Space: the 2D or 3D state space a track runs in, chosen once; what differs between
// the two (window, initial particle, keeping a particle sane, the negatives' cylinder,
// the 2D size filter, the depth correction) asked of it without frames or a tracker.
#include <catch2/catch.hpp>

#include "cuetrack/core/tracker/Space.hpp"

using namespace cuetrack;

namespace {
constexpr int W = 160, H = 120;
const CameraIntrinsics kK{130.f, 130.f, 80.f, 60.f};
IntegralChannels gChannels;  // large: static storage
ParticleFilter gFilter;
}  // namespace

TEST_CASE("Space 2D: the particle is its window, kept sane, no cylinder", "[core][space]") {
  Space s;
  s.configure(false);
  s.start(false, kK, W, H);
  CHECK_FALSE(s.is3d());
  CHECK_FALSE(s.sizesCylinder());
  CHECK(s.cueSearchesScales());
  const Box b{40.f, 30.f, 20.f, 10.f};
  const Particle q = s.initial(b, 0.f);
  const Box w = s.window(q);
  CHECK(w.x == b.x);
  CHECK(w.y == b.y);
  CHECK(w.w == b.w);
  CHECK(w.h == b.h);
  // A window larger than the image and far outside it comes back to at most the image,
  // at least half inside.
  Particle far = q;
  far.p[0] = 1000.f;
  far.size[0] = 500.f;
  s.keepSane(far);
  const Box fw = s.window(far);
  CHECK(fw.w == static_cast<float>(W));
  CHECK(fw.x + 0.5f * fw.w <= static_cast<float>(W));
  NegativeSampler::Cylinder c;
  CHECK(s.negativesCylinder(gChannels, q, &c) == nullptr);
  CHECK(s.initialPositives() == tuning::training::kInitialPositives2d);
  // The size filter smooths a jump in size; the position stays the box's.
  s.resetSize(b);
  const Box doubled{40.f, 30.f, 40.f, 20.f};
  const Box f = s.filterSize(doubled);
  CHECK(f.w < doubled.w);
  CHECK(f.w > b.w);
  CHECK(f.x + 0.5f * f.w == Approx(doubled.x + 0.5f * doubled.w));
}

TEST_CASE("Space 3D: a cylinder seen through the camera, sizes adapt, a negatives' cylinder",
          "[core][space]") {
  Space s;
  s.configure(true);
  s.start(true, kK, W, H);
  CHECK(s.is3d());
  CHECK(s.sizesCylinder());
  CHECK_FALSE(s.cueSearchesScales());  // the depth sets the scale
  const Box b{60.f, 40.f, 26.f, 26.f};
  const Particle q = s.initial(b, 1500.f);
  CHECK(q.p[2] > 1500.f);  // the centre stands behind the surface seen
  const Box w = s.window(q);
  CHECK(w.w == Approx(b.w).margin(0.01f));
  CHECK(w.x + 0.5f * w.w == Approx(b.x + 0.5f * b.w).margin(0.01f));
  NegativeSampler::Cylinder c;
  const NegativeSampler::Cylinder* p = s.negativesCylinder(gChannels, q, &c);
  REQUIRE(p == &c);
  CHECK(c.diameterMm == q.size[0]);
  CHECK(c.imageW == W);
  // The size filter is 2D's: in 3D the estimate's box is kept as it is.
  const Box doubled{60.f, 40.f, 52.f, 52.f};
  CHECK(s.filterSize(doubled).w == doubled.w);
  // A cylinder whose centre left the image is brought back into view.
  Particle out = q;
  out.p[0] = 5000.f;
  s.keepSane(out);
  const Box ow = s.window(out);
  CHECK(ow.x + 0.5f * ow.w <= static_cast<float>(W));
  // Without depth, the depth correction leaves every particle where it was.
  gFilter.setSize(4);
  gFilter.fill(q);
  Box boxes[4] = {};
  FastMotion fast;
  s.correctDepths(false, 1.f / 30.f, gChannels, fast, gFilter, boxes);
  CHECK(gFilter[3].p[2] == q.p[2]);
  CHECK(boxes[3].empty());
}

TEST_CASE("Space: the motion step moves a particle and keeps it sane", "[core][space]") {
  Space s;
  s.configure(false);
  s.start(false, kK, W, H);
  const Particle q = s.initial(Box{40.f, 30.f, 20.f, 20.f}, 0.f);
  Rng a(7), b(7);
  FastMotion fast;
  fast.configure(false);
  Particle p1 = q, p2 = q;
  s.predict(0, p1, fast, a, 1.f / 30.f, 1.f, 1);
  s.predict(0, p2, fast, b, 1.f / 30.f, 1.f, 1);
  CHECK(p1.p[0] != q.p[0]);   // the noise moved it
  CHECK(p1.p[0] == p2.p[0]);  // the same draws, the same step
}

TEST_CASE("Space: which windows are scored, and the 3D position reported", "[core][space]") {
  Space s;
  s.configure(false);
  s.start(false, kK, W, H);
  const Box halfOut{-15.f, 10.f, 30.f, 30.f};
  CHECK(s.scorable(halfOut, false));       // tracking: touching the image is enough
  CHECK_FALSE(s.scorable(halfOut, true));  // searching: mostly inside it
  CHECK_FALSE(s.scorable(Box{10.f, 10.f, 3.f, 30.f}, false));  // under 4 px a side
  CHECK_FALSE(s.scorable(Box{W + 1.f, 10.f, 30.f, 30.f}, false));
  TrackResult r;
  const Particle q = s.initial(Box{60.f, 40.f, 26.f, 26.f}, 0.f);
  s.report(&r, q, s.window(q), gChannels);
  CHECK_FALSE(r.hasPosition3d);  // 2D: no position
  s.start(true, kK, W, H);
  const Particle c = s.initial(Box{60.f, 40.f, 26.f, 26.f}, 1500.f);
  // gChannels has tabulated nothing: no valid depth anywhere.
  s.report(&r, c, s.window(c), gChannels);
  CHECK(r.hasPosition3d);
  CHECK(r.positionMm[2] == c.p[2]);
  CHECK(r.depthPredicted);  // no valid depth in its box
}
