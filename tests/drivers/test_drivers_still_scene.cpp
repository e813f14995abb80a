// A synthetic scene's objects drawn into a real RGB-D still (SyntheticSource::setBackdrop,
// placeInStill): the z-test against the still's depth, the still kept outside the objects,
// the objects' depth through the Kinect model, their shadow cast on the still, the truth.
// The stills here are made in memory (no OpenCV): the library runs on the board too.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "AllocCounter.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"
#include "cuetrack/drivers/StillPlacement.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;

namespace {

constexpr int kW = 640, kH = 480;
constexpr CameraIntrinsics kStillK{525.f, 523.f, 319.5f, 239.5f};  // not the scenes' own

// A still: a textured wall at wallMm, with a hole (no reading) over the rectangle given.
struct Still {
  Rgb8 rgb[kW * kH];
  uint16_t depthMm[kW * kH];
  Still(uint16_t wallMm, int holeX0 = 0, int holeY0 = 0, int holeX1 = 0, int holeY1 = 0) {
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const int i = y * kW + x;
        rgb[i] = {static_cast<uint8_t>(40 + x / 4), static_cast<uint8_t>(30 + y / 3),
                  static_cast<uint8_t>(((x / 16) ^ (y / 16)) & 1 ? 200 : 90)};
        const bool hole = x >= holeX0 && x < holeX1 && y >= holeY0 && y < holeY1;
        depthMm[i] = hole ? 0 : wallMm;
      }
  }
};

SceneSpec scene(const char* name, int frames) {
  SceneSpec s;
  REQUIRE(makeScene(name, &s));
  s.frameCount = frames;
  return s;
}

// The source with the still as its backdrop; the still must outlive it.
std::unique_ptr<SyntheticSource> inStill(const SceneSpec& spec, const Still& still) {
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  src->setBackdrop(still.rgb, still.depthMm, kStillK);
  return src;
}

bool inside(const Box& b, int x, int y, int marginPx) {
  return x >= b.x - marginPx && x < b.x + b.w + marginPx && y >= b.y - marginPx &&
         y < b.y + b.h + marginPx;
}

}  // namespace

TEST_CASE("placeInStill: the target's start on the pixel, its back gapMm before the surface",
          "[synth][still]") {
  auto still = std::make_unique<Still>(2000);
  SceneSpec spec = scene("occlusion", 1);  // two objects: both move by one offset
  const float occluderBefore[3] = {
      spec.objects[1].motion.startMm[0] - spec.objects[0].motion.startMm[0],
      spec.objects[1].motion.startMm[1] - spec.objects[0].motion.startMm[1],
      spec.objects[1].motion.startMm[2] - spec.objects[0].motion.startMm[2]};
  char err[256] = "";
  REQUIRE(
      placeInStill(&spec, still->depthMm, kW, kH, kStillK, 400.f, 200.f, 60.f, err, sizeof err));
  const float* c = spec.objects[0].motion.startMm;
  // The cylinder's back (centre + radius) 60 mm before the wall, on the ray through 400,200.
  CHECK(c[2] + spec.objects[0].radiusMm == Approx(2000.f - 60.f));
  CHECK(kStillK.cx + kStillK.fx * c[0] / c[2] == Approx(400.f));
  CHECK(kStillK.cy + kStillK.fy * c[1] / c[2] == Approx(200.f));
  for (int a = 0; a < 3; ++a)
    CHECK(spec.objects[1].motion.startMm[a] - c[a] == Approx(occluderBefore[a]).margin(1e-3));

  // A flat box turned at t = 0 reaches further back than its half-depth.
  SceneSpec turned = scene("turn", 1);
  turned.objects[0].yawRad = 0.5f;
  CHECK(targetBackMm(turned) == Approx(std::sin(0.5f) * turned.objects[0].radiusMm +
                                       std::cos(0.5f) * turned.objects[0].halfDepthMm));

  // The surface's depth is the median of the readings near the pixel; holes are left out.
  auto holey = std::make_unique<Still>(1500, 100, 100, 104, 200);
  holey->depthMm[150 * kW + 105] = 9000;  // one outlier
  CHECK(stillDepthNear(holey->depthMm, kW, kH, 102, 150) == 1500);
  CHECK(stillDepthNear(holey->depthMm, kW, kH, 104, 150, 1) == 1500);
  CHECK(stillDepthNear(holey->depthMm, kW, kH, 101, 150, 0) == 0);
}

TEST_CASE("placeInStill: a place it cannot use is one line naming why", "[synth][still]") {
  auto still = std::make_unique<Still>(900, 300, 200, 340, 240);
  const auto fails = [&](float u, float v, float gapMm, const char* expect) {
    SceneSpec spec = scene("moving", 1);
    const SceneSpec before = spec;
    char err[256] = "";
    INFO(u << "," << v << " gap " << gapMm);
    CHECK_FALSE(placeInStill(&spec, still->depthMm, kW, kH, kStillK, u, v, gapMm, err, sizeof err));
    INFO(err);
    CHECK(std::strstr(err, expect) != nullptr);
    CHECK(std::strchr(err, '\n') == nullptr);
    CHECK(std::memcmp(&spec.objects[0].motion, &before.objects[0].motion, sizeof(MotionSpec)) == 0);
  };
  fails(320.f, 220.f, 60.f, "no depth within 5 px of 320,220 (a hole)");
  fails(700.f, 10.f, 60.f, "pixel 700,10 lies outside the 640x480 still");
  fails(-1.f, 10.f, 60.f, "outside");
  fails(100.f, 100.f, 400.f, "nearer than 500 mm (the surface at 100,100 is 900 mm away)");
}

TEST_CASE("backdrop: the target's depth is the object's, everything else is the still",
          "[synth][still]") {
  // A wall at 2 m with a hole behind the target's right half: holes hide nothing.
  auto still = std::make_unique<Still>(2000, 330, 0, 400, 480);
  SceneSpec spec = scene("flat-turn", 3);  // face-on at t = 0: its front is flat
  char err[256] = "";
  REQUIRE(
      placeInStill(&spec, still->depthMm, kW, kH, kStillK, 320.f, 240.f, 80.f, err, sizeof err));
  auto src = inStill(spec, *still);
  auto slot = std::make_unique<FrameSlot>();
  for (int f = 0; f < 3; ++f) {
    INFO("frame " << f);
    REQUIRE(src->next(*slot) == ReadStatus::Ok);
    REQUIRE(slot->rgb.width() == kW);
    // The still's intrinsics, as given (not the scenes' scaled Kinect defaults).
    CHECK(slot->intrinsics.fx == kStillK.fx);
    CHECK(slot->intrinsics.cy == kStillK.cy);
    const SynthTruth& t = src->truth();
    const Box gt = slot->groundTruth;
    REQUIRE_FALSE(gt.empty());
    CHECK(t.visiblePixels == t.projectedPixels);          // nothing nearer: all of it in view
    CHECK(gt.x + gt.w / 2 == Approx(320.f).margin(8.f));  // it drifts right at 80 mm/s
    const float frontMm = t.centreMm[2] - spec.objects[0].halfDepthMm;
    CHECK(frontMm == Approx(2000.f - 80.f - 2.f * spec.objects[0].halfDepthMm).margin(1.f));
    // One raw step at this depth is ~11 mm; the noise (sigma 0.35 steps) stays within two.
    const float stepMm = 0.0030711f * frontMm * frontMm / 1000.f;
    int onTarget = 0, shadowLeft = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const int i = y * kW + x;
        const uint16_t d = slot->depthMm.data()[i];
        const Rgb8 c = slot->rgb.data()[i], s = still->rgb[i];
        if (inside(gt, x, y, -3)) {
          ++onTarget;
          REQUIRE(d != 0);
          REQUIRE(std::fabs(d - frontMm) <= 2.f * stepMm + 1.f);
          REQUIRE(kinect::rawToMm(kinect::mmToRaw(d)) == d);  // whole raw steps
        } else if (!inside(gt, x, y, 4)) {
          // The still, its depth exact, its colour within the noise (+-2 levels).
          REQUIRE(d == still->depthMm[i]);
          REQUIRE(std::abs(c.r - s.r) <= 2);
          REQUIRE(std::abs(c.g - s.g) <= 2);
          REQUIRE(std::abs(c.b - s.b) <= 2);
        } else if (x < gt.x && d == 0 && still->depthMm[i] != 0) {
          ++shadowLeft;  // the projector's shadow, cast on the still
        }
      }
    }
    CHECK(onTarget > 5000);
    CHECK(shadowLeft > gt.h / 2);
  }
  // Fresh colour noise each frame, on the still as well.
  auto again = inStill(spec, *still);
  auto other = std::make_unique<FrameSlot>();
  REQUIRE(again->render(0, *slot));
  REQUIRE(again->render(1, *other));
  CHECK(std::memcmp(slot->rgb.data(), other->rgb.data(), 100 * 3) != 0);
}

TEST_CASE("backdrop: a target behind a real surface is hidden, and the truth says so",
          "[synth][still]") {
  // The scene's target at 1.6-2.8 m; the still's surface at 1.2 m hides it everywhere.
  auto near = std::make_unique<Still>(1200);
  const SceneSpec spec = scene("moving", 5);
  auto src = inStill(spec, *near);
  auto slot = std::make_unique<FrameSlot>();
  for (int f = 0; f < 5; ++f) {
    INFO("frame " << f);
    REQUIRE(src->next(*slot) == ReadStatus::Ok);
    CHECK(slot->hasGroundTruth);
    CHECK(slot->groundTruth.empty());  // BoBoT's "not visible"
    CHECK(src->truth().visiblePixels == 0);
    CHECK(src->truth().projectedPixels > 1000);  // it is there, behind
    CHECK(std::memcmp(slot->depthMm.data(), near->depthMm, sizeof near->depthMm) == 0);
  }
  // A surface just before its right half only (2.4 m; the target's front at 2.6 m): the
  // left half is seen, the truth keeps the whole target's box (as the synthetic scenes'
  // truth does for a partly hidden target).
  auto half = std::make_unique<Still>(3500);
  REQUIRE(src->render(0, *slot));
  const Box whole = src->truth().projectedBox;
  REQUIRE(src->truth().centreMm[2] - spec.objects[0].radiusMm > 2500.f);
  const int split = static_cast<int>(whole.x + whole.w / 2);
  for (int y = 0; y < kH; ++y)
    for (int x = split; x < kW; ++x) half->depthMm[y * kW + x] = 2400;
  auto halfSrc = inStill(spec, *half);
  REQUIRE(halfSrc->render(0, *slot));
  const SynthTruth& t = halfSrc->truth();
  CHECK(t.visiblePixels > 0);
  CHECK(t.visibleFraction() == Approx(0.5).margin(0.1));
  CHECK(slot->groundTruth.x == whole.x);
  CHECK(slot->groundTruth.w == whole.w);
  const int y = static_cast<int>(whole.y + whole.h / 2);
  const uint16_t* d = slot->depthMm.data() + y * kW;
  CHECK(d[split + 2] == 2400);  // the real surface in front
  const int seen = static_cast<int>(whole.x + whole.w / 4);
  CHECK(d[seen] > 2500);  // the target
  CHECK(d[seen] < 2900);
}

TEST_CASE("backdrop: no allocation per frame, same bytes for a seed", "[synth][still][alloc]") {
  auto still = std::make_unique<Still>(2500, 0, 0, 100, 480);
  SceneSpec spec = scene("held", 20);
  char err[256] = "";
  REQUIRE(
      placeInStill(&spec, still->depthMm, kW, kH, kStillK, 300.f, 250.f, 300.f, err, sizeof err));
  auto a = inStill(spec, *still);
  auto b = inStill(spec, *still);
  auto fa = std::make_unique<FrameSlot>();
  auto fb = std::make_unique<FrameSlot>();
  REQUIRE(a->next(*fa) == ReadStatus::Ok);
  {
    test::AllocScope scope;
    for (int f = 1; f < 20; ++f) REQUIRE(a->next(*fa) == ReadStatus::Ok);
    CHECK(scope.allocations() == 0);
  }
  REQUIRE(b->render(19, *fb));
  CHECK(std::memcmp(fa->rgb.data(), fb->rgb.data(), sizeof(Rgb8) * kW * kH) == 0);
  CHECK(std::memcmp(fa->depthMm.data(), fb->depthMm.data(), sizeof(uint16_t) * kW * kH) == 0);
}
