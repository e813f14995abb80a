// The 2D estimate's two smoothers: the size filter and the init template's anchor.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/IntegralChannels.hpp"
#include "cuetrack/core/Rng.hpp"
#include "cuetrack/core/SizeFilter.hpp"
#include "cuetrack/core/TemplateAnchor.hpp"

using namespace cuetrack;

namespace {

constexpr int W = 160, H = 120;

// A target with smooth random shading (a few low-frequency waves, as a real object's
// grey levels vary) on a flat grey background; the tables are large (MiBs), so static.
struct Scene {
  Rgb8 rgb[W * H];
  IntegralChannels channels;
  void draw(const Box& target, uint32_t seed, bool textured) {
    Rng r(seed);
    float fx[3], fy[3], ph[3];
    for (int k = 0; k < 3; ++k) {
      fx[k] = r.uniform(0.05f, 0.2f);
      fy[k] = r.uniform(0.05f, 0.2f);
      ph[k] = r.uniform(0.f, 6.28f);
    }
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const bool in =
            x >= target.x && x < target.x + target.w && y >= target.y && y < target.y + target.h;
        float v = 128.f;
        if (in && textured)
          for (int k = 0; k < 3; ++k)
            v += 30.f * std::sin(fx[k] * static_cast<float>(x) + ph[k]) *
                 std::cos(fy[k] * static_cast<float>(y));
        const uint8_t g = static_cast<uint8_t>(v);
        rgb[y * W + x] = Rgb8{g, g, g};
      }
    Frame f;
    f.rgb = RgbView{rgb, W, H, W};
    channels.compute(f, PixelRect{0, 0, W, H}, false);
  }
};
Scene gScene;

// The scene drawn with a textured target at `target`, and the anchor's template taken there.
void captureOn(const Box& target, TemplateAnchor* anchor) {
  gScene.draw(target, 11, true);
  anchor->configure(TemplateAnchor::Params{});
  REQUIRE(anchor->capture(gScene.channels.tables(), target));
}

float sizeError(const Box& a, const Box& b) {
  return std::fabs(std::log(a.w / b.w)) + std::fabs(std::log(a.h / b.h));
}

}  // namespace

TEST_CASE("the size filter damps jitter and follows a steady zoom", "[core][estimate]") {
  SizeFilter2d f;
  f.configure(0.3f, 0.05f);
  REQUIRE(f.enabled());
  const Box start{50.f, 40.f, 40.f, 60.f};
  f.reset(start);
  // Jitter of +-6% around a fixed size: the filtered sizes err about half as much.
  Rng r(3);
  float worstIn = 0.f, worstOut = 0.f;
  for (int i = 0; i < 200; ++i) {
    const float s = std::exp(0.06f * r.gaussian());
    const Box in{start.x, start.y, start.w * s, start.h * s};
    const Box out = f.filter(in);
    // The centre is kept.
    CHECK(out.x + 0.5f * out.w == Approx(in.x + 0.5f * in.w).margin(1e-3));
    CHECK(out.y + 0.5f * out.h == Approx(in.y + 0.5f * in.h).margin(1e-3));
    if (i >= 20) {
      worstIn += sizeError(in, start);
      worstOut += sizeError(out, start);
    }
  }
  CHECK(worstOut < 0.7f * worstIn);
  // A steady zoom of 1% a frame: after settling, no lag (the rate term).
  f.reset(start);
  Box out{};
  for (int i = 1; i <= 120; ++i) {
    const float s = std::exp(0.01f * static_cast<float>(i));
    out = f.filter(Box{start.x, start.y, start.w * s, start.h * s});
  }
  CHECK(std::log(out.w / start.w) == Approx(1.2f).margin(0.01f));
  // Off (alpha 1) is what the presets without it rely on.
  SizeFilter2d off;
  off.configure(1.f, 0.f);
  CHECK_FALSE(off.enabled());
}

TEST_CASE("the template anchor pulls a drifted size and centre back to the init box",
          "[core][estimate]") {
  const Box target{50.f, 30.f, 48.f, 56.f};
  TemplateAnchor anchor;
  captureOn(target, &anchor);
  CHECK(anchor.match(gScene.channels.tables(), target) == Approx(1.f).margin(1e-4));

  // An estimate 8% too small and 2 px off: repeated corrections converge on the target.
  Box est{target.x + 4.f, target.y + 2.f, target.w * 0.92f, target.h * 0.92f};
  const float before = sizeError(est, target);
  for (int i = 0; i < 30; ++i) est = anchor.correct(gScene.channels.tables(), est);
  CHECK(sizeError(est, target) < 0.4f * before);
  CHECK(std::fabs(est.x + 0.5f * est.w - (target.x + 0.5f * target.w)) < 1.5f);
  CHECK(std::fabs(est.y + 0.5f * est.h - (target.y + 0.5f * target.h)) < 1.5f);

  // The right box stays (within a step's rounding).
  const Box kept = anchor.correct(gScene.channels.tables(), target);
  CHECK(sizeError(kept, target) < 0.02f);
}

TEST_CASE("the template anchor leaves the estimate alone when the target no longer matches",
          "[core][estimate]") {
  const Box target{50.f, 30.f, 48.f, 56.f};
  TemplateAnchor anchor;
  captureOn(target, &anchor);
  // Another texture where the target was (it turned, or something hides it).
  gScene.draw(target, 99, true);
  const Box est{target.x + 3.f, target.y, target.w * 0.9f, target.h * 0.9f};
  const Box out = anchor.correct(gScene.channels.tables(), est);
  CHECK(out.x == est.x);
  CHECK(out.y == est.y);
  CHECK(out.w == est.w);
  CHECK(out.h == est.h);
  // A flat window gives no template, and the anchor stays inactive.
  gScene.draw(target, 11, false);
  TemplateAnchor flat;
  flat.configure(TemplateAnchor::Params{});
  CHECK_FALSE(flat.capture(gScene.channels.tables(), target));
  CHECK_FALSE(flat.active());
  CHECK(flat.match(gScene.channels.tables(), target) == -2.f);
}
