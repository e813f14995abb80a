// Synthetic scenes: determinism, exact ground truth, the Kinect-like depth model and
// no allocation per frame.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>

#include "AllocCounter.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;

namespace {

SceneSpec scene(const char* name, int frames) {
  SceneSpec s;
  REQUIRE(makeScene(name, &s));
  s.frameCount = frames;
  return s;
}

bool sameFrame(const FrameSlot& a, const FrameSlot& b) {
  const size_t n = static_cast<size_t>(a.rgb.width()) * static_cast<size_t>(a.rgb.height());
  return a.rgb.width() == b.rgb.width() && a.rgb.height() == b.rgb.height() &&
         std::memcmp(a.rgb.data(), b.rgb.data(), n * 3) == 0 &&
         std::memcmp(a.depthMm.data(), b.depthMm.data(), n * 2) == 0 && a.timeUs == b.timeUs;
}

// Mean of the valid depth inside a box [mm]; 0 when none.
double meanDepth(const FrameSlot& f, const Box& b) {
  double sum = 0;
  int n = 0;
  for (int y = static_cast<int>(b.y); y < static_cast<int>(b.y + b.h); ++y)
    for (int x = static_cast<int>(b.x); x < static_cast<int>(b.x + b.w); ++x) {
      const uint16_t d = f.depthMm.data()[y * f.depthMm.width() + x];
      if (d) {
        sum += d;
        ++n;
      }
    }
  return n ? sum / n : 0.0;
}

}  // namespace

TEST_CASE("Kinect raw <-> mm conversion round-trips within one raw step", "[synth][kinect]") {
  CHECK(kinect::rawToMm(kinect::kRawNoDepth) == 0);
  CHECK(kinect::mmToRaw(0) == kinect::kRawNoDepth);
  CHECK(kinect::rawToMm(0) == 300);   // 1 / 3.3309495161 m
  CHECK(kinect::rawToMm(1100) == 0);  // beyond the fit's pole
  for (int raw = 0; raw < 1060; ++raw) {
    const uint16_t mm = kinect::rawToMm(static_cast<uint16_t>(raw));
    if (mm == 0) continue;
    // Exact inverse of every depth the conversion produces.
    CHECK(kinect::rawToMm(kinect::mmToRaw(mm)) == mm);
  }
  for (int mm = 500; mm <= 8000; mm += 7) {
    const uint16_t back = kinect::rawToMm(kinect::mmToRaw(static_cast<uint16_t>(mm)));
    // Half a raw step: dz/draw = 0.0030711 z^2 [m]
    const double halfStepMm = 0.5 * 0.0030711016 * (mm / 1000.0) * (mm / 1000.0) * 1000.0 + 1.0;
    CHECK(std::abs(back - mm) <= halfStepMm);
  }
}

TEST_CASE("every named scene renders with ground truth on the target", "[synth]") {
  REQUIRE(sceneCount() >= 6);
  CHECK(sceneName(sceneCount()) == nullptr);
  SceneSpec bad;
  CHECK_FALSE(makeScene("no-such-scene", &bad));
  auto slot = std::make_unique<FrameSlot>();
  for (int i = 0; i < sceneCount(); ++i) {
    INFO(sceneName(i));
    auto src = std::make_unique<SyntheticSource>(scene(sceneName(i), 3), 7);
    REQUIRE(src->frameCount() == 3);
    int n = 0;
    while (src->next(*slot) == ReadStatus::Ok) {
      CHECK(slot->index == n);
      CHECK(slot->rgb.width() == 640);
      CHECK(slot->rgb.height() == 480);
      CHECK(slot->hasDepth);
      CHECK(slot->hasGroundTruth);
      CHECK(slot->intrinsics.fx == Approx(kKinectV1Intrinsics.fx));
      CHECK(slot->timeUs == static_cast<uint64_t>(std::llround(n * 1e6 / 30.0)));
      ++n;
    }
    CHECK(n == 3);
    CHECK(src->next(*slot) == ReadStatus::End);
  }
}

TEST_CASE("same seed gives the same bytes, another seed other noise", "[synth]") {
  const SceneSpec spec = scene("moving", 4);
  auto a = std::make_unique<SyntheticSource>(spec, 42);
  auto b = std::make_unique<SyntheticSource>(spec, 42);
  auto c = std::make_unique<SyntheticSource>(spec, 43);
  auto fa = std::make_unique<FrameSlot>(), fb = std::make_unique<FrameSlot>(),
       fc = std::make_unique<FrameSlot>();
  for (int i = 0; i < 4; ++i) {
    REQUIRE(a->next(*fa) == ReadStatus::Ok);
    REQUIRE(b->next(*fb) == ReadStatus::Ok);
    REQUIRE(c->next(*fc) == ReadStatus::Ok);
    CHECK(sameFrame(*fa, *fb));
    CHECK_FALSE(sameFrame(*fa, *fc));
    CHECK(fa->groundTruth.x == fc->groundTruth.x);  // truth does not depend on noise
  }
  // render() is random access: frame 2 again equals what next() gave.
  REQUIRE(a->render(3, *fb));
  CHECK(sameFrame(*fa, *fb));
}

// Inclusive pixel bounds {x0, y0, x1, y1} of where a 640x480 frame differs from the
// background-only render (colour, and depth too when asked); x1 = -1 when nowhere.
static std::array<int, 4> changedPixels(const FrameSlot& a, const FrameSlot& bg, bool depthToo) {
  std::array<int, 4> r{1 << 20, 1 << 20, -1, -1};
  for (int y = 0; y < 480; ++y)
    for (int x = 0; x < 640; ++x) {
      const int i = y * 640 + x;
      if ((depthToo && a.depthMm.data()[i] != bg.depthMm.data()[i]) ||
          std::memcmp(&a.rgb.data()[i], &bg.rgb.data()[i], 3) != 0) {
        r[0] = std::min(r[0], x);
        r[1] = std::min(r[1], y);
        r[2] = std::max(r[2], x);
        r[3] = std::max(r[3], y);
      }
    }
  return r;
}

TEST_CASE("ground truth box matches the rendered target pixels", "[synth]") {
  SceneSpec spec = scene("moving", 30);
  spec.colourNoise = 0;
  spec.disparityNoiseRaw = 0;
  auto src = std::make_unique<SyntheticSource>(spec, 1);
  auto slot = std::make_unique<FrameSlot>();
  // Render the background alone (no objects) to find the target pixels as the difference.
  SceneSpec empty = spec;
  empty.objects[0].motion.startMm[2] = -5000.f;  // behind the camera: not drawn
  auto bg = std::make_unique<SyntheticSource>(empty, 1);
  auto bgSlot = std::make_unique<FrameSlot>();
  for (int f = 0; f < 30; f += 7) {
    REQUIRE(src->render(f, *slot));
    REQUIRE(bg->render(f, *bgSlot));
    const auto [x0, y0, x1, y1] = changedPixels(*slot, *bgSlot, true);
    const Box gt = slot->groundTruth;
    INFO("frame " << f << " gt " << gt.x << "," << gt.y << " " << gt.w << "x" << gt.h << " px "
                  << x0 << "," << y0 << ".." << x1 << "," << y1);
    REQUIRE(x1 >= 0);
    // Pixel centres of the changed pixels lie inside the box, touching its edges
    // (the shadow strip left of the target also changes: allow it on the left).
    CHECK(x0 >= gt.x - 12);
    CHECK(y0 >= gt.y - 1.5f);
    CHECK(x1 + 0.5f <= gt.x + gt.w + 1.5f);
    CHECK(y1 + 0.5f <= gt.y + gt.h + 1.5f);
    CHECK(x1 + 0.5f >= gt.x + gt.w - 1.5f);
    CHECK(y1 + 0.5f >= gt.y + gt.h - 1.5f);
    // The depth inside the box's central part is the target's front surface.
    const SynthTruth& t = src->truth();
    const Box core{gt.x + gt.w * 0.35f, gt.y + gt.h * 0.25f, gt.w * 0.3f, gt.h * 0.5f};
    CHECK(meanDepth(*slot, core) == Approx(t.centreMm[2] - t.radiusMm).margin(30));
    // Projection of the 3D centre lies inside the box.
    const float u = slot->intrinsics.cx + slot->intrinsics.fx * t.centreMm[0] / t.centreMm[2];
    CHECK(u > gt.x);
    CHECK(u < gt.x + gt.w);
  }
}

TEST_CASE("occlusion scene hides the target completely for a while, then shows it", "[synth]") {
  auto src = std::make_unique<SyntheticSource>(scene("occlusion", 150), 3);
  auto slot = std::make_unique<FrameSlot>();
  int hidden = 0, partial = 0, visibleAfter = 0;
  bool wasHidden = false;
  // Every third frame keeps the test quick under qemu; the target is hidden for ~24 frames.
  for (int f = 0; f < 150; f += 3) {
    REQUIRE(src->render(f, *slot));
    const SynthTruth& t = src->truth();
    CHECK(t.projectedPixels > 0);
    if (t.visiblePixels == 0) {
      ++hidden;
      wasHidden = true;
      CHECK(slot->groundTruth.empty());
    } else {
      CHECK_FALSE(slot->groundTruth.empty());
      if (t.visibleFraction() < 0.9f) ++partial;
      if (wasHidden) ++visibleAfter;
    }
  }
  CHECK(hidden >= 5);
  CHECK(partial >= 2);
  CHECK(visibleAfter >= 10);
}

TEST_CASE("twin-crossing: the twin has the target's texture and crosses it further back",
          "[synth]") {
  SceneSpec spec = scene("twin-crossing", 150);
  REQUIRE(spec.numObjects == 2);
  CHECK(std::memcmp(&spec.objects[0].texture, &spec.objects[1].texture, sizeof(TextureSpec)) == 0);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  float a[3], b[3];
  src->objectPosition(0, 0.f, a);
  src->objectPosition(1, 0.f, b);
  CHECK(a[0] / a[2] < b[0] / b[2]);  // target starts left of the twin
  src->objectPosition(0, 4.9f, a);
  src->objectPosition(1, 4.9f, b);
  CHECK(a[0] / a[2] > b[0] / b[2]);  // and ends right of it
  CHECK(b[2] - a[2] >= 500.f);
}

TEST_CASE("approach scene: the box grows at least 4x", "[synth]") {
  auto src = std::make_unique<SyntheticSource>(scene("approach", 150), 3);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->render(0, *slot));
  const float h0 = slot->groundTruth.h;
  REQUIRE(src->render(149, *slot));
  CHECK(slot->groundTruth.h > 4.f * h0);
}

TEST_CASE("turn scene: the box yaws 90 degrees, its width shrinks ~3x, truth follows it",
          "[synth]") {
  SceneSpec spec = scene("turn", 150);
  spec.colourNoise = 0;
  spec.disparityNoiseRaw = 0;
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  SceneSpec empty = spec;
  empty.objects[0].motion.startMm[2] = -5000.f;  // behind the camera: not drawn
  auto bg = std::make_unique<SyntheticSource>(empty, 3);
  auto bgSlot = std::make_unique<FrameSlot>();
  float w0 = 0.f;
  for (int f : {0, 40, 75, 110, 149}) {
    REQUIRE(src->render(f, *slot));
    REQUIRE(bg->render(f, *bgSlot));
    const auto [x0, y0, x1, y1] = changedPixels(*slot, *bgSlot, false);
    const Box gt = slot->groundTruth;
    INFO("frame " << f << " gt " << gt.x << "," << gt.y << " " << gt.w << "x" << gt.h << " px "
                  << x0 << "," << y0 << ".." << x1 << "," << y1);
    REQUIRE(x1 >= 0);
    // The colour changes are the target itself (no shadow in colour): the box's silhouette.
    CHECK(std::abs(x0 - gt.x) <= 1.5f);
    CHECK(std::abs(y0 - gt.y) <= 1.5f);
    CHECK(std::abs(x1 + 1 - (gt.x + gt.w)) <= 1.5f);
    CHECK(std::abs(y1 + 1 - (gt.y + gt.h)) <= 1.5f);
    CHECK(gt.x > 0.f);  // inside the image all along
    CHECK(gt.x + gt.w < 640.f);
    // Depth on the ray through the box's centre: where that ray leaves the yawed box
    // towards the camera (the ray parameter is camera depth).
    const SynthTruth& t = src->truth();
    const float dx = t.centreMm[0] / t.centreMm[2], dy = t.centreMm[1] / t.centreMm[2];
    const float c = std::cos(t.yawRad), sn = std::sin(t.yawRad);
    const float lx = std::abs(c * dx + sn), lz = std::abs(-sn * dx + c);
    const float back = std::min({lx > 0.f ? 200.f / lx : 1e9f, 60.f / lz, 100.f / std::abs(dy)});
    const int cu = static_cast<int>(slot->intrinsics.cx + slot->intrinsics.fx * dx);
    const int cv = static_cast<int>(slot->intrinsics.cy + slot->intrinsics.fy * dy);
    CHECK(slot->depthMm.data()[cv * 640 + cu] == Approx(t.centreMm[2] - back).margin(20));
    if (f == 0) w0 = gt.w;
    if (f == 149) CHECK(gt.w < w0 / 2.5f);
  }
  CHECK(w0 > 90.f);
}

TEST_CASE("untextured scene: colour cannot see the target, depth can", "[synth]") {
  SceneSpec spec = scene("untextured", 1);
  spec.colourNoise = 0;
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->next(*slot) == ReadStatus::Ok);
  const Rgb8 first = slot->rgb.data()[0];
  int differing = 0;
  for (int i = 0; i < 640 * 480; ++i)
    differing += std::memcmp(&slot->rgb.data()[i], &first, 3) != 0;
  CHECK(differing == 0);
  const Box gt = slot->groundTruth;
  const Box inner{gt.x + gt.w * 0.3f, gt.y + gt.h * 0.3f, gt.w * 0.4f, gt.h * 0.4f};
  const Box right{gt.x + gt.w + 20, gt.y, gt.w, gt.h};
  CHECK(meanDepth(*slot, right) - meanDepth(*slot, inner) > 1000.0);
}

TEST_CASE("lighting scene changes brightness, not the geometry", "[synth]") {
  SceneSpec spec = scene("lighting", 150);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  auto mean = [&](int f) {
    REQUIRE(src->render(f, *slot));
    double s = 0;
    for (int i = 0; i < 640 * 480; ++i) s += slot->rgb.data()[i].g;
    return s / (640 * 480);
  };
  const double before = mean(70), after = mean(80);  // the lights dim at frame 75
  CHECK(after < 0.75 * before);
}

TEST_CASE("depth model: quantised to raw steps, range limits and shadows", "[synth]") {
  SceneSpec spec = scene("moving", 1);
  auto src = std::make_unique<SyntheticSource>(spec, 5);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->next(*slot) == ReadStatus::Ok);
  int holes = 0;
  for (int i = 0; i < 640 * 480; ++i) {
    const uint16_t d = slot->depthMm.data()[i];
    if (d == 0) {
      ++holes;
      continue;
    }
    // Every value is the depth of some raw disparity.
    REQUIRE(kinect::rawToMm(kinect::mmToRaw(d)) == d);
    CHECK(d >= 450);
  }
  CHECK(holes > 0);  // the out-of-range opening on the left
  // A shadow strip left of the target: background depth missing just left of its box.
  const Box gt = slot->groundTruth;
  const int y = static_cast<int>(gt.y + gt.h / 2);
  int shadow = 0;
  for (int x = static_cast<int>(gt.x) - 15; x < static_cast<int>(gt.x); ++x)
    shadow += slot->depthMm.data()[y * 640 + x] == 0;
  CHECK(shadow >= 3);
  // No shadows when switched off.
  spec.shadows = false;
  auto noShadow = std::make_unique<SyntheticSource>(spec, 5);
  REQUIRE(noShadow->next(*slot) == ReadStatus::Ok);
  shadow = 0;
  for (int x = static_cast<int>(gt.x) - 15; x < static_cast<int>(gt.x); ++x)
    shadow += slot->depthMm.data()[y * 640 + x] == 0;
  CHECK(shadow == 0);
}

TEST_CASE("configurable size scales intrinsics and truth", "[synth]") {
  SceneSpec spec = scene("moving", 1);
  spec.width = 320;
  spec.height = 240;
  auto src = std::make_unique<SyntheticSource>(spec, 5);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->next(*slot) == ReadStatus::Ok);
  CHECK(slot->rgb.width() == 320);
  CHECK(slot->intrinsics.fx == Approx(kKinectV1Intrinsics.fx / 2));
  CHECK(slot->groundTruth.x + slot->groundTruth.w <= 320.f);
  SceneSpec tooBig = spec;
  tooBig.width = 2000;
  auto bad = std::make_unique<SyntheticSource>(tooBig, 5);
  CHECK(bad->next(*slot) == ReadStatus::Error);
  CHECK(std::strstr(bad->error(), "size") != nullptr);
}

TEST_CASE("no allocation per synthetic frame", "[synth][alloc]") {
  {
    test::AllocScope control;
    auto p = std::make_unique<int>(3);
    REQUIRE(control.allocations() >= 1);  // the counter works
  }
  auto src = std::make_unique<SyntheticSource>(scene("twin-crossing", 10), 9);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->next(*slot) == ReadStatus::Ok);
  test::AllocScope scope;
  int n = 1;
  while (src->next(*slot) == ReadStatus::Ok) ++n;
  CHECK(n == 10);
  CHECK(scope.allocations() == 0);
}

TEST_CASE("synthetic frames are the same bytes on x86, aarch64 and armhf", "[synth][golden]") {
  // FNV-1a over colour + depth. The library is built with -ffp-contract=off so no
  // platform fuses multiply-adds. A deliberate change of a scene or of the depth model
  // changes these: regenerate them then (print `h` below), in the same commit.
  struct Golden {
    const char* scene;
    int frame;
    uint64_t hash;
  };
  const Golden golden[] = {
      {"occlusion", 0, 0xd9dccb0788bc30f1ull},  {"occlusion", 70, 0x1eb28688b530445full},
      {"occlusion", 80, 0x25eddac899d125aaull}, {"lighting", 0, 0x0ccdc56fdf4bc560ull},
      {"lighting", 70, 0xf6c4eed439afec41ull},  {"lighting", 80, 0xdca6fc4bedac2694ull},
  };
  auto slot = std::make_unique<FrameSlot>();
  for (const Golden& g : golden) {
    auto src = std::make_unique<SyntheticSource>(scene(g.scene, 150), 42);
    REQUIRE(src->render(g.frame, *slot));
    uint64_t h = 1469598103934665603ull;
    auto fnv = [&h](const void* p, size_t n) {
      const uint8_t* b = static_cast<const uint8_t*>(p);
      for (size_t i = 0; i < n; ++i) {
        h ^= b[i];
        h *= 1099511628211ull;
      }
    };
    fnv(slot->rgb.data(), 640 * 480 * 3);
    fnv(slot->depthMm.data(), 640 * 480 * 2);
    INFO(g.scene << " frame " << g.frame << " hash 0x" << std::hex << h);
    CHECK(h == g.hash);
  }
}
