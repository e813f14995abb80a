// Synthetic scenes: determinism, exact ground truth, the Kinect-like depth model and
// no allocation per frame.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "AllocCounter.hpp"
#include "FrameHash.hpp"
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

TEST_CASE("the scene catalogue: one row per name, an unknown name lists them", "[synth]") {
  std::set<std::string> names;
  for (int i = 0; i < sceneCount(); ++i) {
    const SceneEntry* e = sceneEntry(i);
    REQUIRE(e != nullptr);
    INFO(e->name);
    CHECK(std::string(e->name) == sceneName(i));
    CHECK(names.insert(e->name).second);  // no name twice
    CHECK(std::string(e->summary).size() > 10);
    CHECK(std::string(e->summary).find('\n') == std::string::npos);
    SceneSpec s;
    REQUIRE(makeScene(e->name, &s));
    CHECK(std::string(s.name) == e->name);
    CHECK(s.numObjects >= 1);
  }
  CHECK(sceneEntry(-1) == nullptr);
  CHECK(sceneEntry(sceneCount()) == nullptr);
  SceneSpec s;
  char err[512] = "";
  CHECK_FALSE(makeScene("nope", &s, err, sizeof err));
  std::string expected = "unknown scene 'nope' (scenes: ";
  for (int i = 0; i < sceneCount(); ++i) expected += std::string(i ? ", " : "") + sceneName(i);
  CHECK(std::string(err) == expected + ")");
  CHECK(makeScene("box", &s, err, sizeof err));
  // Each scene is its own: no two rows build the same spec (a missing builder once
  // rendered as box).
  SceneSpec a, b;
  REQUIRE(makeScene("box", &a));
  for (int i = 0; i < sceneCount(); ++i) {
    if (std::string(sceneName(i)) == "box") continue;
    INFO(sceneName(i));
    REQUIRE(makeScene(sceneName(i), &b));
    const SceneObject &x = a.objects[0], &y = b.objects[0];
    CHECK_FALSE((x.shape == y.shape && x.radiusMm == y.radiusMm && x.heightMm == y.heightMm &&
                 x.texture.seed == y.texture.seed && x.motion.startMm[0] == y.motion.startMm[0] &&
                 x.motion.startMm[2] == y.motion.startMm[2]));
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

namespace {
// Centre of a box [px].
float centreX(const Box& b) {
  return b.x + b.w * 0.5f;
}
float centreY(const Box& b) {
  return b.y + b.h * 0.5f;
}
bool insideImage(const Box& b) {
  return !b.empty() && b.x >= 0.f && b.y >= 0.f && b.x + b.w <= 640.f && b.y + b.h <= 480.f;
}
// Zero-depth share over the pixels of columns [x0, x1) and rows [y0, y1), clipped to the image.
double zeroShare(const FrameSlot& f, int x0, int x1, int y0, int y1) {
  int zeros = 0, n = 0;
  for (int y = std::max(y0, 0); y < std::min(y1, 480); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, 640); ++x) {
      zeros += f.depthMm.data()[y * 640 + x] == 0;
      ++n;
    }
  return n ? static_cast<double>(zeros) / n : 0.0;
}
// Median of the valid depths over columns [x0, x1), rows [y0, y1) [mm]; 0 when none.
int medianDepth(const FrameSlot& f, int x0, int x1, int y0, int y1) {
  std::vector<uint16_t> d;
  for (int y = std::max(y0, 0); y < std::min(y1, 480); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, 640); ++x)
      if (const uint16_t v = f.depthMm.data()[y * 640 + x]) d.push_back(v);
  if (d.empty()) return 0;
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  return d[d.size() / 2];
}
}  // namespace

TEST_CASE("fast: the target's box moves about 40 px every frame and stays in view", "[synth]") {
  auto src = std::make_unique<SyntheticSource>(scene("fast", 150), 3);
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(src->spec().objects[0].motion.triangleAmplitudeMm[0] > 0.f);
  // Pairs of consecutive frames, every third pair (quick under qemu): 50 steps.
  int steps = 0, fastSteps = 0;
  for (int f = 0; f + 1 < 150; f += 3) {
    REQUIRE(src->render(f, *slot));
    const Box a = src->truth().projectedBox;
    REQUIRE(src->render(f + 1, *slot));
    const Box b = src->truth().projectedBox;
    CHECK(insideImage(a));
    CHECK(insideImage(b));
    CHECK(src->truth().visibleFraction() == 1.f);
    const float d = std::hypot(centreX(b) - centreX(a), centreY(b) - centreY(a));
    INFO("frame " << f << " step " << d);
    CHECK(d < 44.f);
    ++steps;
    fastSteps += d >= 38.f;
  }
  CHECK(fastSteps >= steps * 9 / 10);
}

TEST_CASE("lookalike: a same-textured cylinder in front hides the target for >= 10 frames",
          "[synth]") {
  SceneSpec spec = scene("lookalike", 150);
  REQUIRE(spec.numObjects == 2);
  const SceneObject& target = spec.objects[spec.targetIndex];
  const SceneObject& look = spec.objects[1 - spec.targetIndex];
  CHECK(look.texture.kind == target.texture.kind);  // the same texture, field by field
  CHECK(std::memcmp(&look.texture.colourA, &target.texture.colourA, sizeof(Rgb8)) == 0);
  CHECK(std::memcmp(&look.texture.colourB, &target.texture.colourB, sizeof(Rgb8)) == 0);
  CHECK(look.texture.seed == target.texture.seed);
  CHECK(look.texture.texelMm == target.texture.texelMm);
  CHECK(look.shape == target.shape);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  // The look-alike's own truth: the same scene with it as the target.
  SceneSpec lookSpec = spec;
  lookSpec.targetIndex = 1 - spec.targetIndex;
  auto lookSrc = std::make_unique<SyntheticSource>(lookSpec, 3);
  auto slot = std::make_unique<FrameSlot>();
  int run = 0, longest = 0;
  for (int f = 40; f < 110; ++f) {
    REQUIRE(src->render(f, *slot));
    const SynthTruth& t = src->truth();
    const bool hidden = t.visiblePixels == 0 && insideImage(t.projectedBox);
    if (hidden) {
      CHECK(slot->groundTruth.empty());
      REQUIRE(lookSrc->render(f, *slot));
      const SynthTruth& l = lookSrc->truth();
      CHECK(l.centreMm[2] < t.centreMm[2] - 500.f);  // in front
      // About the target's image size, a bit larger (it must cover it).
      CHECK(l.projectedBox.w >= t.projectedBox.w);
      CHECK(l.projectedBox.w <= 1.5f * t.projectedBox.w);
      CHECK(l.projectedBox.h <= 1.5f * t.projectedBox.h);
    }
    run = hidden ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  CHECK(longest >= 10);
  // Seen whole before and after.
  for (int f : {0, 30, 120, 149}) {
    REQUIRE(src->render(f, *slot));
    CHECK(src->truth().visibleFraction() == 1.f);
  }
}

TEST_CASE("leave-return: out of view for exactly 30 frames, back elsewhere, stays", "[synth]") {
  auto src = std::make_unique<SyntheticSource>(scene("leave-return", 150), 3);
  auto slot = std::make_unique<FrameSlot>();
  int emptyFrames = 0, runs = 0, firstEmpty = -1;
  bool wasEmpty = false;
  Box lastBefore{}, firstAfter{};
  for (int f = 0; f < 150; ++f) {
    REQUIRE(src->render(f, *slot));
    const bool empty = slot->groundTruth.empty();
    CHECK(empty == src->truth().projectedBox.empty());  // out of view, not hidden
    if (empty) {
      ++emptyFrames;
      if (!wasEmpty) {
        ++runs;
        firstEmpty = f;
      }
    } else if (runs == 0) {
      lastBefore = slot->groundTruth;
    } else if (firstAfter.empty()) {
      firstAfter = slot->groundTruth;
    }
    wasEmpty = empty;
  }
  CHECK(runs == 1);
  CHECK(emptyFrames == 30);
  CHECK(firstEmpty > 0);
  CHECK_FALSE(wasEmpty);  // in view at the end
  INFO("left at x " << centreX(lastBefore) << ", back at x " << centreX(firstAfter));
  CHECK(centreX(lastBefore) > 600.f);  // left on the right
  CHECK(centreX(firstAfter) < 40.f);   // back on the left
  CHECK(std::hypot(centreX(firstAfter) - centreX(lastBefore),
                   centreY(firstAfter) - centreY(lastBefore)) >= 200.f);
}

TEST_CASE("against-surface: the depth just outside the target is the board's, close behind",
          "[synth]") {
  SceneSpec spec = scene("against-surface", 150);
  REQUIRE(spec.numObjects == 2);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  int frames = 0, close = 0;
  for (int f = 0; f < 150; f += 5) {
    REQUIRE(src->render(f, *slot));
    const Box gt = slot->groundTruth;
    const SynthTruth& t = src->truth();
    REQUIRE(insideImage(gt));
    CHECK(t.visibleFraction() == 1.f);
    CHECK(gt.w < 80.f);  // the bag alone (the board is ~500 px wide)
    // Columns 3..6 px beyond the box's left edge (past the projector's ~1 px shadow) and
    // 2..5 px beyond its right edge, over the middle half of its rows.
    const int y0 = static_cast<int>(gt.y + gt.h * 0.25f),
              y1 = static_cast<int>(gt.y + gt.h * 0.75f);
    const int xl = static_cast<int>(gt.x), xr = static_cast<int>(std::ceil(gt.x + gt.w));
    const int left = medianDepth(*slot, xl - 6, xl - 2, y0, y1);
    const int right = medianDepth(*slot, xr + 2, xr + 6, y0, y1);
    const float z = t.centreMm[2];
    INFO("frame " << f << " centre z " << z << " left " << left << " right " << right);
    CHECK(left > z);  // behind the target: the board
    CHECK(right > z);
    ++frames;
    close += std::abs(left - z) <= 100.f && std::abs(right - z) <= 100.f;
  }
  CHECK(close >= frames * 8 / 10);
}

TEST_CASE("held: a skin-coloured hand in front hides 10-40 % of the target", "[synth]") {
  SceneSpec spec = scene("held", 150);
  REQUIRE(spec.numObjects == 2);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  const SceneObject& hand = spec.objects[1 - spec.targetIndex];
  CHECK(hand.texture.colourA.r > hand.texture.colourA.g);  // skin: red > green > blue
  CHECK(hand.texture.colourA.g > hand.texture.colourA.b);
  int frames = 0, inRange = 0;
  for (int f = 0; f < 150; f += 2) {
    REQUIRE(src->render(f, *slot));
    const float v = src->truth().visibleFraction();
    INFO("frame " << f << " visible " << v);
    CHECK(v > 0.f);
    ++frames;
    inRange += v >= 0.6f && v <= 0.9f;
    float h[3], c[3];
    src->objectPosition(1 - spec.targetIndex, static_cast<float>(f) / 30.f, h);
    src->objectPosition(spec.targetIndex, static_cast<float>(f) / 30.f, c);
    CHECK(h[2] < c[2] - 100.f);  // nearer the camera
  }
  CHECK(inRange >= frames * 8 / 10);
}

TEST_CASE("flat-turn: a flat box turns face-on -> nearly edge-on -> face-on", "[synth]") {
  auto src = std::make_unique<SyntheticSource>(scene("flat-turn", 150), 3);
  auto slot = std::make_unique<FrameSlot>();
  const SceneObject& b = src->spec().objects[0];
  CHECK(b.shape == ShapeKind::Box);
  CHECK(b.halfDepthMm * 4.f <= b.radiusMm);  // flat
  float minW = 1e9f, maxW = 0.f, maxYaw = 0.f;
  for (int f = 0; f < 150; f += 3) {
    REQUIRE(src->render(f, *slot));
    const Box gt = slot->groundTruth;
    CHECK(insideImage(gt));
    minW = std::min(minW, gt.w);
    maxW = std::max(maxW, gt.w);
    maxYaw = std::max(maxYaw, src->truth().yawRad);
  }
  INFO("width " << minW << " .. " << maxW << ", yaw up to " << maxYaw);
  CHECK(maxW >= 2.f * minW);
  CHECK(maxYaw < 1.45f);  // never edge-on (pi / 2)
  CHECK(maxYaw > 1.2f);
  REQUIRE(src->render(149, *slot));
  CHECK(src->truth().yawRad < 0.05f);  // face-on again at the end
}

TEST_CASE("no-depth: the target reads no depth in frames 40-109 only, the rest keeps it",
          "[synth]") {
  SceneSpec spec = scene("no-depth", 150);
  REQUIRE(spec.targetNoDepthFirst == 40);
  REQUIRE(spec.targetNoDepthLast == 109);
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  for (int f : {0, 39, 40, 75, 109, 110, 149}) {
    INFO("frame " << f);
    REQUIRE(src->render(f, *slot));
    const Box gt = slot->groundTruth;
    REQUIRE(insideImage(gt));
    // The middle of the target's box is the target; a band right of it (the projector's
    // shadow falls on the left) is the wall.
    const int cx = static_cast<int>(centreX(gt));
    const int y0 = static_cast<int>(gt.y + gt.h * 0.3f), y1 = static_cast<int>(gt.y + gt.h * 0.7f);
    const double target = zeroShare(*slot, cx - 5, cx + 5, y0, y1);
    const int xr = static_cast<int>(gt.x + gt.w) + 20;
    const double wall = zeroShare(*slot, xr, xr + 10, y0, y1);
    const bool dropped = f >= 40 && f <= 109;
    CHECK(target == (dropped ? 1.0 : 0.0));
    CHECK(wall < 0.05);
  }
}

TEST_CASE("edge-holes: depth drops out along the target's silhouette, only when asked", "[synth]") {
  SceneSpec spec = scene("edge-holes", 150);
  REQUIRE(spec.edgeHoleProbability > 0.f);
  SceneSpec off = spec;
  off.edgeHoleProbability = 0.f;
  auto on = std::make_unique<SyntheticSource>(spec, 3);
  auto plain = std::make_unique<SyntheticSource>(off, 3);
  auto slot = std::make_unique<FrameSlot>();
  auto plainSlot = std::make_unique<FrameSlot>();
  double shareOn = 0, shareOff = 0, coreOn = 0, coreOff = 0;
  int frames = 0;
  for (int f = 0; f < 150; f += 10) {
    REQUIRE(on->render(f, *slot));
    REQUIRE(plain->render(f, *plainSlot));
    const Box gt = slot->groundTruth;
    REQUIRE(insideImage(gt));
    CHECK(plainSlot->groundTruth.x == gt.x);  // the same scene otherwise
    // Bands along the box's left and right edges (where the cylinder's silhouette runs),
    // over the middle 60 % of its rows: 3 px inside on the left (the projector's shadow is
    // outside there anyway), 3 px inside and 3 px outside on the right; and its centre.
    const int y0 = static_cast<int>(gt.y + gt.h * 0.2f), y1 = static_cast<int>(gt.y + gt.h * 0.8f);
    const int xl = static_cast<int>(gt.x + 0.5f), xr = static_cast<int>(gt.x + gt.w + 0.5f);
    auto band = [&](const FrameSlot& s) {
      return 0.5 * (zeroShare(s, xl, xl + 3, y0, y1) + zeroShare(s, xr - 3, xr + 3, y0, y1));
    };
    const int cx = static_cast<int>(centreX(gt));
    shareOn += band(*slot);
    shareOff += band(*plainSlot);
    coreOn += zeroShare(*slot, cx - 5, cx + 5, y0, y1);
    coreOff += zeroShare(*plainSlot, cx - 5, cx + 5, y0, y1);
    ++frames;
  }
  shareOn /= frames;
  shareOff /= frames;
  INFO("zero depth on the edge bands: " << shareOn << " with, " << shareOff << " without");
  CHECK(shareOn >= 0.2);
  CHECK(shareOn >= 3.0 * shareOff + 0.1);
  CHECK(coreOn == coreOff);  // the target's inside keeps its depth
  // Colour and ground truth do not change; another seed drops other pixels.
  REQUIRE(on->render(30, *slot));
  REQUIRE(plain->render(30, *plainSlot));
  CHECK(std::memcmp(slot->rgb.data(), plainSlot->rgb.data(), 640 * 480 * 3) == 0);
  auto other = std::make_unique<SyntheticSource>(spec, 4);
  REQUIRE(other->render(30, *plainSlot));
  CHECK(std::memcmp(slot->depthMm.data(), plainSlot->depthMm.data(), 640 * 480 * 2) != 0);
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
  // The edge dropout pass and the moving, jumping and turning motions too.
  for (const char* name : {"edge-holes", "leave-return", "flat-turn", "fast"}) {
    INFO(name);
    auto other = std::make_unique<SyntheticSource>(scene(name, 150), 9);
    REQUIRE(other->render(0, *slot));
    test::AllocScope again;
    for (int f = 70; f < 80; ++f) REQUIRE(other->render(f, *slot));
    CHECK(again.allocations() == 0);
  }
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
      {"occlusion", 0, 0xd9dccb0788bc30f1ull},
      {"occlusion", 70, 0x1eb28688b530445full},
      {"occlusion", 80, 0x25eddac899d125aaull},
      {"lighting", 0, 0x0ccdc56fdf4bc560ull},
      {"lighting", 70, 0xf6c4eed439afec41ull},
      {"lighting", 80, 0xdca6fc4bedac2694ull},
      // The scenes added with the triangle wave, the jump, the yaw sway and edge dropout.
      {"fast", 0, 0xa5d17f8acd009dacull},
      {"fast", 6, 0x0d98039a91c580c8ull},
      {"lookalike", 75, 0x6816df2979c5e093ull},
      {"leave-return", 78, 0xcfb6a4f80162cf7bull},
      {"against-surface", 60, 0xc204f4c4d853d32aull},
      {"held", 45, 0xcf856b1c0e2834d8ull},
      {"flat-turn", 75, 0x66a8178efdcf8ea0ull},
      {"edge-holes", 40, 0x4901a31a81dae561ull},
      {"no-depth", 60, 0x6f2055ac9f2d77ddull},  // the target's depth dropped
  };
  auto slot = std::make_unique<FrameSlot>();
  for (const Golden& g : golden) {
    auto src = std::make_unique<SyntheticSource>(scene(g.scene, 150), 42);
    REQUIRE(src->render(g.frame, *slot));
    const uint64_t h = test::frameHash(*slot);
    INFO(g.scene << " frame " << g.frame << " hash 0x" << std::hex << h);
    CHECK(h == g.hash);
  }
}
