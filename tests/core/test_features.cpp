// Every feature kind against a brute-force computation on small images, on frame
// tables (with and without an ROI origin) and on example patches.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/Features.hpp"
#include "cuetrack/core/Integral.hpp"
#include "cuetrack/core/IntegralChannels.hpp"
#include "cuetrack/core/TrainingSet.hpp"

using namespace cuetrack;

namespace {

constexpr int W = 48, H = 40;

struct TestImage {
  Rgb8 rgb[W * H];
  uint16_t depth[W * H];
  Frame frame() const {
    Frame f;
    f.rgb = RgbView{rgb, W, H, W};
    f.depthMm = DepthView{depth, W, H, W};
    f.intrinsics = kKinectV1Intrinsics;
    return f;
  }
};

void fill(TestImage& im, uint32_t seed, bool holes) {
  Rng r(seed);
  for (int i = 0; i < W * H; ++i) {
    im.rgb[i] = Rgb8{static_cast<uint8_t>(r.below(256)), static_cast<uint8_t>(r.below(256)),
                     static_cast<uint8_t>(r.below(256))};
    im.depth[i] = static_cast<uint16_t>(800 + r.below(3000));
    if (holes && r.below(5) == 0) im.depth[i] = 0;
  }
}

int grayOf(const Rgb8& p) {
  return (77 * p.r + 150 * p.g + 29 * p.b + 128) >> 8;
}

// Brute force: mean of a channel over [x0,x1) x [y0,y1) of the full image.
double meanGray(const TestImage& im, int x0, int y0, int x1, int y1) {
  double s = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) s += grayOf(im.rgb[y * W + x]);
  return s / ((x1 - x0) * (y1 - y0));
}
bool meanDepth(const TestImage& im, int x0, int y0, int x1, int y1, double* out) {
  double s = 0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const uint16_t d = im.depth[y * W + x];
      if (d == 0) continue;
      s += d;
      ++n;
    }
  *out = n ? s / n : 0;
  return 2 * n >= (x1 - x0) * (y1 - y0);
}

static IntegralChannels channels;  // large: static storage

}  // namespace

TEST_CASE("gray, depth and colour features match brute force on frames", "[core][features]") {
  static TestImage im;
  fill(im, 3, true);
  const PixelRect rois[2] = {{0, 0, W, H}, {5, 3, W - 2, H - 1}};
  for (const PixelRect& roi : rois) {
    channels.compute(im.frame(), roi, true);
    const FrameTables& t = channels.tables();
    Rng r(11);
    for (int trial = 0; trial < 300; ++trial) {
      Feature f;
      f.w = r.uniform(0.2f, 0.8f);
      f.h = r.uniform(0.2f, 0.8f);
      f.x = r.uniform(0.f, 1.f - f.w);
      f.y = r.uniform(0.f, 1.f - f.h);
      f.kind = static_cast<FeatureKind>(trial % 3);
      const Box win{static_cast<float>(roi.x0) + r.uniform(0.f, 8.f),
                    static_cast<float>(roi.y0) + r.uniform(0.f, 6.f), r.uniform(12.f, 30.f),
                    r.uniform(12.f, 28.f)};
      // The same rounding the feature uses, in frame coordinates.
      const int x0 = fmath::roundToInt(win.x + f.x * win.w);
      int x1 = fmath::roundToInt(win.x + f.x * win.w + f.w * win.w);
      const int y0 = fmath::roundToInt(win.y + f.y * win.h);
      int y1 = fmath::roundToInt(win.y + f.y * win.h + f.h * win.h);
      x1 = x0 + ((x1 - x0) & ~1);  // even sizes: equal halves
      y1 = y0 + ((y1 - y0) & ~1);
      REQUIRE(x1 <= roi.x1);
      REQUIRE(y1 <= roi.y1);
      const int xm = (x0 + x1) / 2, ym = (y0 + y1) / 2;
      const Response resp = evaluate(f, win, t);
      double gx = 0, gy = 0;
      bool valid = true;
      if (f.kind == FeatureKind::Gray) {
        gx = meanGray(im, xm, y0, x1, y1) - meanGray(im, x0, y0, xm, y1);
        gy = meanGray(im, x0, ym, x1, y1) - meanGray(im, x0, y0, x1, ym);
      } else if (f.kind == FeatureKind::Depth) {
        double l, rr, tt, b;
        valid = meanDepth(im, x0, y0, xm, y1, &l) & meanDepth(im, xm, y0, x1, y1, &rr) &
                meanDepth(im, x0, y0, x1, ym, &tt) & meanDepth(im, x0, ym, x1, y1, &b);
        gx = rr - l;
        gy = b - tt;
      } else {
        double a = 0, be = 0;
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) {
            const Rgb8 p = im.rgb[y * W + x];
            a += 0.5 * (2 * p.r - p.g - p.b);
            be += std::sqrt(3.0) / 2 * (p.g - p.b);
          }
        gx = a / ((x1 - x0) * (y1 - y0));
        gy = be / ((x1 - x0) * (y1 - y0));
      }
      REQUIRE(resp.valid == valid);
      if (!valid) continue;
      const double mag = std::sqrt(gx * gx + gy * gy);
      REQUIRE(resp.mag() == Approx(mag).margin(1e-3 * (1 + mag)));
      if (mag > 0.5) {
        double ang = std::atan2(gy, gx);
        if (ang < 0) ang += 2 * M_PI;
        double d = std::fabs(resp.angle() - ang);
        if (d > M_PI) d = 2 * M_PI - d;
        REQUIRE(d < 1e-3);
      }
    }
  }
}

TEST_CASE("missing depth never makes a gradient", "[core][features]") {
  static TestImage im;
  fill(im, 5, false);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) im.depth[y * W + x] = x < W / 2 ? 0 : 1500;  // left half: holes
  channels.compute(im.frame(), PixelRect{0, 0, W, H}, true);
  Feature f;
  f.kind = FeatureKind::Depth;
  // Straddling the hole edge: the left half has no valid pixel -> no measurement.
  const Response across = evaluate(f, Box{8.f, 4.f, 32.f, 32.f}, channels.tables());
  REQUIRE_FALSE(across.valid);
  // Entirely on valid flat depth: a valid, zero gradient (not a 1500 mm step).
  const Response flat = evaluate(f, Box{26.f, 4.f, 20.f, 20.f}, channels.tables());
  REQUIRE(flat.valid);
  REQUIRE(flat.mag() < 1e-3f);
  // Sparse holes (< half) in a flat region: still a zero gradient, not a hole artefact.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) im.depth[y * W + x] = ((x + y) % 3 == 0) ? 0 : 1500;
  channels.compute(im.frame(), PixelRect{0, 0, W, H}, true);
  const Response sparse = evaluate(f, Box{4.f, 4.f, 30.f, 30.f}, channels.tables());
  REQUIRE(sparse.valid);
  REQUIRE(sparse.mag() < 1e-3f);
}

TEST_CASE("a frame without depth gives no depth measurement", "[core][features]") {
  static TestImage im;
  fill(im, 9, false);
  Frame f = im.frame();
  f.depthMm = DepthView{};
  channels.compute(f, PixelRect{0, 0, W, H}, true);
  Feature d;
  d.kind = FeatureKind::Depth;
  REQUIRE_FALSE(evaluate(d, Box{0.f, 0.f, 30.f, 30.f}, channels.tables()).valid);
}

TEST_CASE("features answer the same on an example patch as on the frame", "[core][features]") {
  // A 32x32 window maps one pixel per patch cell: the patch is then exact.
  static TestImage im;
  fill(im, 21, true);
  channels.compute(im.frame(), PixelRect{0, 0, W, H}, true);
  const Box win{7.f, 5.f, 32.f, 32.f};
  static ExamplePatch patch;
  extractPatch(channels.tables(), win, &patch);
  Rng r(2);
  for (int trial = 0; trial < 200; ++trial) {
    Feature f;
    f.w = r.uniform(0.15f, 0.9f);
    f.h = r.uniform(0.15f, 0.9f);
    f.x = r.uniform(0.f, 1.f - f.w);
    f.y = r.uniform(0.f, 1.f - f.h);
    f.kind = static_cast<FeatureKind>(trial % 3);
    const Response a = evaluate(f, win, channels.tables());
    const Response b = evaluate(f, ExamplePatch::window(), patch.tables());
    REQUIRE(a.valid == b.valid);
    if (!a.valid) continue;
    REQUIRE(b.mag() == Approx(a.mag()).margin(2e-2 + 1e-3 * a.mag()));
  }
  // A larger window is area-averaged: gradients of a smooth ramp keep their value.
  static TestImage ramp;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const uint8_t v = static_cast<uint8_t>(4 * x);
      ramp.rgb[y * W + x] = Rgb8{v, v, v};
      ramp.depth[y * W + x] = static_cast<uint16_t>(1000 + 10 * y);
    }
  channels.compute(ramp.frame(), PixelRect{0, 0, W, H}, true);
  extractPatch(channels.tables(), Box{0.f, 0.f, 48.f, 40.f}, &patch);
  Feature g;
  g.kind = FeatureKind::Gray;
  const Response onFrame = evaluate(g, Box{0.f, 0.f, 48.f, 40.f}, channels.tables());
  const Response onPatch = evaluate(g, ExamplePatch::window(), patch.tables());
  REQUIRE(onPatch.mag() == Approx(onFrame.mag()).epsilon(0.06));
  REQUIRE(onFrame.angle() < 0.05f);  // brightening to the right: angle 0
}
