// Where a learning step's negatives lie (NegativeSampler).
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/model/NegativeSampler.hpp"

using namespace cuetrack;

namespace {
constexpr int W = 320, H = 240;
uint16_t gDepth[W * H];
Rgb8 gRgb[W * H];
IntegralChannels gChannels;  // large: static

// A D x H mm cylinder seen by a Kinect, over the depth in gChannels.
NegativeSampler::Cylinder cylinder(float diameterMm, float heightMm) {
  NegativeSampler::Cylinder c;
  c.channels = &gChannels;
  c.k = kKinectV1Intrinsics;
  c.diameterMm = diameterMm;
  c.heightMm = heightMm;
  c.imageW = W;
  c.imageH = H;
  return c;
}

bool near(float a, float b) {
  return std::fabs(a - b) < 1e-3f;
}
}  // namespace

TEST_CASE("2D negatives: near misses and background, none on the estimate", "[core][negatives]") {
  NegativeSampler s;
  s.configure(NegativeSampler::Params{});
  const Box est{120.f, 80.f, 40.f, 60.f};
  const PixelRect roi{0, 0, W, H};
  Rng rng(5);
  int scaled = 0, shifted = 0, background = 0, cornerAnchored = 0;
  for (int step = 0; step < 50; ++step) {
    for (int k = 0; k < 10; ++k) {
      const Box b = s.next(k, est, roi, nullptr, rng);
      INFO("k " << k << " box " << b.x << "," << b.y << "," << b.w << "," << b.h);
      const float o = overlap(b, est);
      if ((k & 1) != 0) {
        // Background: well away from the estimate, inside the ROI.
        CHECK(o < NegativeSampler::kMaxOverlap);
        CHECK(b.x >= 0.f);
        CHECK(b.y >= 0.f);
        CHECK(b.x + b.w <= static_cast<float>(W) + 1e-3f);
        CHECK(b.y + b.h <= static_cast<float>(H) + 1e-3f);
        ++background;
      } else if ((k & 2) == 0) {
        // Scaled by 0.65 or 1/0.65 along one axis or both, anchored at the start, centre
        // or end of each axis.
        const float sw = b.w / est.w, sh = b.h / est.h;
        CHECK((near(sw, 1.f) || near(sw, 0.65f) || near(sw, 1.f / 0.65f)));
        CHECK((near(sh, 1.f) || near(sh, 0.65f) || near(sh, 1.f / 0.65f)));
        CHECK_FALSE((near(sw, 1.f) && near(sh, 1.f)));
        const bool ax = near(b.x, est.x) || near(b.x + b.w, est.x + est.w) ||
                        near(b.x + 0.5f * b.w, est.x + 0.5f * est.w);
        const bool ay = near(b.y, est.y) || near(b.y + b.h, est.y + est.h) ||
                        near(b.y + 0.5f * b.h, est.y + 0.5f * est.h);
        CHECK(ax);
        CHECK(ay);
        if (!near(b.x + 0.5f * b.w, est.x + 0.5f * est.w) ||
            !near(b.y + 0.5f * b.h, est.y + 0.5f * est.h))
          ++cornerAnchored;
        ++scaled;
      } else {
        // Shifted by 20% of the side along one axis, same size.
        CHECK(near(b.w, est.w));
        CHECK(near(b.h, est.h));
        const float dx = std::fabs(b.x - est.x), dy = std::fabs(b.y - est.y);
        CHECK(((near(dx, 0.2f * est.w) && near(dy, 0.f)) ||
               (near(dy, 0.2f * est.h) && near(dx, 0.f))));
        ++shifted;
      }
    }
  }
  CHECK(scaled == 150);
  CHECK(shifted == 100);
  CHECK(background == 250);
  CHECK(cornerAnchored > 50);  // not all concentric
  // In 3D (a cylinder given) the scaled near misses stay concentric.
  const NegativeSampler::Cylinder cyl = cylinder(300.f, 500.f);
  for (int k = 0; k < 40; k += 4) {
    const Box b = s.next(k, est, roi, &cyl, rng);
    CHECK(near(b.x + 0.5f * b.w, est.x + 0.5f * est.w));
    CHECK(near(b.y + 0.5f * b.h, est.y + 0.5f * est.h));
  }
}

TEST_CASE("3D background negatives take the cylinder's size at the depth where they lie",
          "[core][negatives]") {
  // Left half of the image at 1 m, right half at 3 m.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      gDepth[y * W + x] = x < W / 2 ? 1000 : 3000;
      gRgb[y * W + x] = Rgb8{100, 100, 100};
    }
  Frame f;
  f.rgb = RgbView{gRgb, W, H, W};
  f.depthMm = DepthView{gDepth, W, H, W};
  f.intrinsics = kKinectV1Intrinsics;
  gChannels.compute(f, PixelRect{0, 0, W, H}, true);
  const NegativeSampler::Cylinder cyl = cylinder(200.f, 400.f);
  NegativeSampler s;
  s.configure(NegativeSampler::Params{});
  const Box est{140.f, 90.f, 40.f, 60.f};
  Rng rng(9);
  const float wNear = cyl.k.fx * 200.f / 1100.f, wFar = cyl.k.fx * 200.f / 3100.f;
  int nearOnes = 0, farOnes = 0;
  for (int i = 0; i < 100; ++i) {
    const Box b = s.next(1, est, PixelRect{0, 0, W, H}, &cyl, rng);
    if (near(b.w, wNear)) {
      CHECK(b.h == Approx(cyl.k.fy * 400.f / 1100.f).epsilon(1e-4));
      ++nearOnes;
    } else if (near(b.w, wFar)) {
      CHECK(b.h == Approx(cyl.k.fy * 400.f / 3100.f).epsilon(1e-4));
      ++farOnes;
    }
  }
  // Both halves are drawn, and (nearly) every window has one of the two sizes (those on
  // the seam average the depths).
  CHECK(nearOnes > 20);
  CHECK(farOnes > 20);
  CHECK(nearOnes + farOnes > 85);
}
