// The depth silhouette behind adaptCylinderSize: a flat slab of known size at a known
// depth in front of a farther wall is measured to the pixel, holes (depth 0) change
// nothing, and a run that goes on to the window's edge is not taken as a size.
#include <catch2/catch.hpp>

#include "cuetrack/core/cues/SizeMeasure.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"

using namespace cuetrack;

namespace {
constexpr int W = 320, H = 240;
constexpr uint16_t kWallMm = 3000, kSlabMm = 1500;
// The slab covers columns [100, 160) and rows [80, 170): 60 x 90 px.
constexpr int kX0 = 100, kX1 = 160, kY0 = 80, kY1 = 170;
uint16_t depth[W * H];
const CameraIntrinsics kK{260.f, 260.f, 160.f, 120.f};

void drawScene() {
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool slab = x >= kX0 && x < kX1 && y >= kY0 && y < kY1;
      // A slightly tilted slab (+-8 mm) and a wall with sensor-like ripple.
      depth[y * W + x] = slab ? static_cast<uint16_t>(kSlabMm - 8 + (x - kX0) * 16 / 60)
                              : static_cast<uint16_t>(kWallMm + (x * 7 + y * 3) % 11);
    }
}

DepthView view() {
  return DepthView{depth, W, H, W};
}

// A window off the slab's centre and smaller than it, as a lagging estimate would be.
const Box kEstimate{108.f, 92.f, 46.f, 70.f};

SilhouetteExtent measure() {
  return measureSilhouette(view(), kEstimate, kSlabMm - 150.f, kSlabMm + 150.f);
}
}  // namespace

TEST_CASE("the silhouette measurement recovers a slab's known width and height", "[core][size]") {
  drawScene();
  const SilhouetteExtent e = measure();
  REQUIRE(e.hasWidth);
  REQUIRE(e.hasHeight);
  REQUIRE(e.widthPx == 60.f);
  REQUIRE(e.heightPx == 90.f);
  REQUIRE(e.centreXPx == 130.f);
  REQUIRE(e.centreYPx == 125.f);
  // As a cylinder whose front surface is on the slab: it projects back onto the slab's
  // rectangle (the init rule), and the slab's real width W = w s / fx lies within D.
  const float dMm = cylinderDiameterMm(e.widthPx, kSlabMm, kK);
  const float hMm = cylinderHeightMm(e.heightPx, kSlabMm, dMm, kK);
  REQUIRE(dMm > 60.f * kSlabMm / kK.fx);
  Particle q;
  q.p[2] = kSlabMm + 0.5f * dMm;
  q.p[0] = (e.centreXPx - kK.cx) * q.p[2] / kK.fx;
  q.p[1] = (e.centreYPx - kK.cy) * q.p[2] / kK.fy;
  q.size[0] = dMm;
  q.size[1] = hMm;
  const Box b = projectCylinder(q, kK);
  REQUIRE(b.x == Approx(kX0).margin(1e-3));
  REQUIRE(b.y == Approx(kY0).margin(1e-3));
  REQUIRE(b.w == Approx(kX1 - kX0).margin(1e-3));
  REQUIRE(b.h == Approx(kY1 - kY0).margin(1e-3));
  // A window larger than the slab measures the same.
  const SilhouetteExtent big =
      measureSilhouette(view(), Box{95.f, 70.f, 75.f, 110.f}, kSlabMm - 150.f, kSlabMm + 150.f);
  REQUIRE((big.hasWidth && big.hasHeight));
  REQUIRE(big.widthPx == 60.f);
  REQUIRE(big.heightPx == 90.f);
}

TEST_CASE("the silhouette measurement ignores missing depth", "[core][size]") {
  drawScene();
  // Every third pixel a hole, a 6 px shadow band (no depth) along the slab's left edge
  // and a 3 px hole across its middle: the same extent.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      uint16_t& d = depth[y * W + x];
      if ((x + 2 * y) % 3 == 0) d = 0;
      if (x >= kX0 - 6 && x < kX0 && y >= kY0 && y < kY1) d = 0;
      if (x >= 128 && x < 131) d = 0;
    }
  const SilhouetteExtent e = measure();
  REQUIRE((e.hasWidth && e.hasHeight));
  REQUIRE(e.widthPx == 60.f);
  REQUIRE(e.heightPx == 90.f);
  // No depth at all: nothing measured (not a size of 0).
  for (uint16_t& d : depth) d = 0;
  const SilhouetteExtent none = measure();
  REQUIRE_FALSE(none.hasWidth);
  REQUIRE_FALSE(none.hasHeight);
  REQUIRE(measureSilhouette(DepthView{}, kEstimate, 1000.f, 2000.f).hasWidth == false);
}

TEST_CASE("a silhouette that runs on to the window's edge is not a size", "[core][size]") {
  drawScene();
  // A shelf at the slab's depth across the whole image behind the slab's middle rows:
  // the width is unknown, the height (measured in the middle columns) still is.
  for (int y = 110; y < 140; ++y)
    for (int x = 0; x < W; ++x) depth[y * W + x] = kSlabMm;
  const SilhouetteExtent e = measure();
  REQUIRE_FALSE(e.hasWidth);
  REQUIRE(e.hasHeight);
  REQUIRE(e.heightPx == 90.f);
  // A second slab cut by the image's left edge: its width is unknown too.
  drawScene();
  for (int y = kY0; y < kY1; ++y)
    for (int x = 0; x < 30; ++x) depth[y * W + x] = kSlabMm;
  const SilhouetteExtent cut =
      measureSilhouette(view(), Box{-10.f, 92.f, 40.f, 70.f}, kSlabMm - 150.f, kSlabMm + 150.f);
  REQUIRE_FALSE(cut.hasWidth);
  REQUIRE(cut.hasHeight);
  REQUIRE(cut.heightPx == 90.f);
}

TEST_CASE("a slab over twice the window's width is measured only in the wide window",
          "[core][size]") {
  drawScene();
  // A window 22 px wide on the 60 px slab (a box that fell behind a target turning back
  // face-on): the default window (22 + 2 x 11 px) lies inside the slab, so its run reaches
  // the window's edge and the width stays unmeasured; the wide one (22 + 2 x 33) holds it.
  const Box narrow{119.f, 92.f, 22.f, 70.f};
  const SilhouetteExtent e = measureSilhouette(view(), narrow, kSlabMm - 150.f, kSlabMm + 150.f);
  CHECK_FALSE(e.hasWidth);
  const SilhouetteExtent wide =
      measureSilhouette(view(), narrow, kSlabMm - 150.f, kSlabMm + 150.f, kSilhouetteWideGrow);
  REQUIRE(wide.hasWidth);
  CHECK(wide.widthPx == 60.f);
  CHECK(wide.centreXPx == 130.f);
  CHECK(wide.hasHeight);
  // The width alone: the same width, no height read.
  const SilhouetteExtent widthOnly =
      measureSilhouette(view(), narrow, kSlabMm - 150.f, kSlabMm + 150.f, kSilhouetteWideGrow,
                        SilhouetteAxes::WidthOnly);
  CHECK(widthOnly.hasWidth);
  CHECK(widthOnly.widthPx == 60.f);
  CHECK(widthOnly.centreXPx == 130.f);
  CHECK_FALSE(widthOnly.hasHeight);
}
