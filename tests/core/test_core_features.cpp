// Every feature kind against a brute-force computation on small images, on frame
// tables (with and without an ROI origin) and on example patches.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/kernels/Integral.hpp"
#include "cuetrack/core/model/Features.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"
#include "cuetrack/core/model/TrainingSet.hpp"

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

// A feature of kind k with sides in [minSide, maxSide) placed at random inside [0,1]^2.
Feature randomFeature(Rng& r, float minSide, float maxSide, FeatureKind k) {
  Feature f;
  f.w = r.uniform(minSide, maxSide);
  f.h = r.uniform(minSide, maxSide);
  f.x = r.uniform(0.f, 1.f - f.w);
  f.y = r.uniform(0.f, 1.f - f.h);
  f.kind = k;
  return f;
}

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
      const Feature f = randomFeature(r, 0.2f, 0.8f, static_cast<FeatureKind>(trial % 3));
      const Box win{static_cast<float>(roi.x0) + r.uniform(0.f, 8.f),
                    static_cast<float>(roi.y0) + r.uniform(0.f, 6.f), r.uniform(12.f, 30.f),
                    r.uniform(12.f, 28.f)};
      // The feature's edges: cell edges of the window's 32x32 grid (Features.hpp), each on
      // the pixel nearest to it; checked against the plain formula, then used.
      int cx[3], cy[3];
      featureCells(f.x, f.w, cx);
      featureCells(f.y, f.h, cy);
      REQUIRE(cx[2] - cx[0] >= 2);
      REQUIRE((cx[2] - cx[0]) % 2 == 0);
      REQUIRE(cx[1] * 2 == cx[0] + cx[2]);
      REQUIRE(std::abs(cx[0] - 32.0 * f.x) <= 0.5 + 1e-4);
      REQUIRE(std::abs(cx[2] - 32.0 * (f.x + f.w)) <= 1.5 + 1e-4);  // evened
      int e[3], g[3];
      for (int i = 0; i < 3; ++i) {
        e[i] = gridEdge(win.x - static_cast<float>(t.originX), win.w, cx[i], t.width) + t.originX;
        g[i] = gridEdge(win.y - static_cast<float>(t.originY), win.h, cy[i], t.height) + t.originY;
        REQUIRE(std::abs(e[i] - (win.x + cx[i] / 32.0 * win.w)) <= 0.5 + 1e-3);
        REQUIRE(std::abs(g[i] - (win.y + cy[i] / 32.0 * win.h)) <= 0.5 + 1e-3);
      }
      const int x0 = e[0], xm = e[1], x1 = e[2], y0 = g[0], ym = g[1], y1 = g[2];
      REQUIRE(x1 <= roi.x1);
      REQUIRE(y1 <= roi.y1);
      if (xm == x0 || x1 == xm || ym == y0 || y1 == ym) {  // an empty half: no measurement
        REQUIRE_FALSE(evaluate(f, win, t).valid);
        continue;
      }
      const Response resp = evaluate(f, win, t);
      double gx = 0, gy = 0;
      bool valid = true;
      if (f.kind == FeatureKind::Gray) {
        gx = meanGray(im, xm, y0, x1, y1) - meanGray(im, x0, y0, xm, y1);
        gy = meanGray(im, x0, ym, x1, y1) -
             meanGray(im, x0, y0, x1, ym);  // halves may differ by 1 px
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
  // A patch keeps the frame's sums at the window's cell edges: every feature, on windows
  // smaller and larger than the 32x32 grid, clipped by the tables' border or not, and
  // with an ROI origin, reads the same pixels on both: the same response, bit for bit.
  static TestImage im;
  fill(im, 21, true);
  static ExamplePatch patch;
  const PixelRect rois[2] = {{0, 0, W, H}, {3, 2, W - 1, H}};
  Rng r(2);
  int compared = 0, invalid = 0;
  for (const PixelRect& roi : rois) {
    channels.compute(im.frame(), roi, true);
    for (int trial = 0; trial < 300; ++trial) {
      const Box win{r.uniform(-6.f, 30.f), r.uniform(-6.f, 24.f), r.uniform(10.f, 60.f),
                    r.uniform(10.f, 50.f)};
      extractPatch(channels.tables(), win, &patch);
      for (int k = 0; k < 6; ++k) {
        const Feature f = randomFeature(r, 0.05f, 0.9f, static_cast<FeatureKind>(k % 3));
        const Response a = evaluate(f, win, channels.tables());
        const Response b = evaluate(f, patch.view());
        REQUIRE(a.valid == b.valid);
        if (!a.valid) {
          ++invalid;
          continue;
        }
        REQUIRE(a.x == b.x);
        REQUIRE(a.y == b.y);
        ++compared;
      }
    }
  }
  REQUIRE(compared > 2000);  // most are measurements...
  REQUIRE(invalid > 20);     // ...and the empty-half cases are exercised too
  // A ramp: the gradient is the difference of the halves' means, on the patch as on the frame.
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
  const Response onPatch = evaluate(g, patch.view());
  REQUIRE(onPatch.x == onFrame.x);
  REQUIRE(onFrame.mag() == Approx(4.0 * 24).epsilon(0.06));  // 4 grey levels a pixel, 24 px apart
  REQUIRE(onFrame.angle() < 0.05f);                          // brightening to the right: angle 0
}
