// Start requests into the pixel box the tracker starts on (StartBox); a typed box that
// reads as corners (BoxFit).
#include <catch2/catch.hpp>

#include <vector>

#include "BoxFit.hpp"
#include "StartBox.hpp"

using namespace cuetrack;
using namespace cuetrack::app;
using platform::StartRequest;

namespace {

struct TestFrame {
  std::vector<Rgb8> rgb = std::vector<Rgb8>(640 * 480);
  std::vector<uint16_t> depth = std::vector<uint16_t>(640 * 480, 0);
  Frame frame(bool withDepth) const {
    Frame f;
    f.rgb = RgbView{rgb.data(), 640, 480, 640};
    if (withDepth) f.depthMm = DepthView{depth.data(), 640, 480, 640};
    f.intrinsics = kKinectV1Intrinsics;
    return f;
  }
};

}  // namespace

TEST_CASE("pixel boxes pass through; normalised rectangles scale by the image") {
  const TestFrame tf;
  StartRequest r;
  r.box = Box{10, 20, 30, 40};
  const Box px = startBoxPx(r, tf.frame(false));
  CHECK(px.x == 10);
  CHECK(px.h == 40);
  r.kind = StartRequest::Kind::BoxNormalised;
  r.box = Box{0.25f, 0.5f, 0.5f, 0.25f};
  const Box n = startBoxPx(r, tf.frame(false));
  CHECK(n.x == Approx(160));
  CHECK(n.y == Approx(240));
  CHECK(n.w == Approx(320));
  CHECK(n.h == Approx(120));
}

TEST_CASE("a point becomes a square sized from the depth there, else the radius, else 1/10") {
  TestFrame tf;
  StartRequest r;
  r.kind = StartRequest::Kind::PointNormalised;
  r.pointX = 0.5f;
  r.pointY = 0.5f;
  r.radius = 0.05f;
  // 2 m away: a 400 mm object is 518 * 0.4 / 2 = 103.6 px wide.
  for (int y = 230; y < 250; ++y)
    for (int x = 310; x < 330; ++x) tf.depth[static_cast<size_t>(y) * 640 + x] = 2000;
  const Box d = startBoxPx(r, tf.frame(true));
  CHECK(d.w == Approx(518.f * kPointTargetMm / 2000.f));
  CHECK(d.x + d.w / 2 == Approx(320));
  CHECK(d.y + d.h / 2 == Approx(240));
  // No depth at the point: the radius (5 % of the width each side).
  r.pointX = 0.1f;
  CHECK(startBoxPx(r, tf.frame(true)).w == Approx(64));
  CHECK(startBoxPx(r, tf.frame(false)).w == Approx(64));
  r.radius = 0.f;
  CHECK(startBoxPx(r, tf.frame(false)).w == Approx(64));  // kPointDefaultWidthFraction
  // Very near or very far: clamped to what the tracker can use.
  r.pointX = 0.5f;
  for (uint16_t& v : tf.depth) v = v ? 300 : 0;
  CHECK(startBoxPx(r, tf.frame(true)).w == Approx(240));  // half the image height
  for (uint16_t& v : tf.depth) v = v ? 60000 : 0;
  CHECK(startBoxPx(r, tf.frame(true)).w == Approx(kPointMinSidePx));
}

TEST_CASE("a box that runs past the image as X,Y,W,H but fits as corners reads as corners") {
  Box xywh{};
  // 100,80 to 600,400 typed as corners on 640x480.
  REQUIRE(looksLikeCorners(Box{100, 80, 600, 400}, 640, 480, &xywh));
  CHECK(xywh.x == 100);
  CHECK(xywh.y == 80);
  CHECK(xywh.w == 500);
  CHECK(xywh.h == 320);
  CHECK(looksLikeCorners(Box{10, 300, 100, 400}, 640, 480, &xywh));  // runs past the bottom
  // Inside the image: X,Y,W,H as given, whatever the numbers.
  CHECK_FALSE(looksLikeCorners(Box{100, 80, 200, 150}, 640, 480, &xywh));
  // Past the edge, but not corners: a box reaching out (x1 <= x0), or too large as corners.
  CHECK_FALSE(looksLikeCorners(Box{600, 10, 100, 100}, 640, 480, &xywh));
  CHECK_FALSE(looksLikeCorners(Box{100, 80, 700, 400}, 640, 480, &xywh));
  CHECK_FALSE(looksLikeCorners(Box{-10, 80, 600, 400}, 640, 480, &xywh));
}
