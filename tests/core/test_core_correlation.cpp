// CorrelationCue: the template found where the texture moved, its response map, its
// learning, and what it refuses (a flat window, a window off the tables).
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/cues/CorrelationCue.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

using namespace cuetrack;

namespace {

constexpr int W = 320, H = 240;

// A gray background with a random-block texture of kTex px at (x, y), 8 px blocks.
struct Scene {
  Rgb8 rgb[W * H];
  void paint(int x, int y, int side, uint32_t seed, uint8_t background = 128) {
    for (Rgb8& p : rgb) p = Rgb8{background, background, background};
    Rng r(seed);
    uint8_t blocks[16 * 16];
    for (uint8_t& b : blocks) b = static_cast<uint8_t>(r.below(256));
    for (int v = 0; v < side; ++v)
      for (int u = 0; u < side; ++u) {
        const int px = x + u, py = y + v;
        if (px < 0 || py < 0 || px >= W || py >= H) continue;
        const uint8_t g = blocks[(v * 16 / side) * 16 + u * 16 / side];
        rgb[py * W + px] = Rgb8{g, g, g};
      }
  }
  Frame frame() const {
    Frame f;
    f.rgb = RgbView{rgb, W, H, W};
    return f;
  }
};

Scene gScene;
IntegralChannels gChannels;  // large: static storage
CorrelationCue gCue;

const FrameTables& tablesOf(const Scene& s, const PixelRect& roi = PixelRect{0, 0, W, H}) {
  gChannels.compute(s.frame(), roi, false);
  return gChannels.tables();
}

}  // namespace

TEST_CASE("CorrelationCue finds the template where the texture moved", "[core][correlation]") {
  constexpr int kSide = 48;
  gScene.paint(100, 80, kSide, 7);
  const Box win{100.f, 80.f, kSide, kSide};
  REQUIRE(gCue.reset(tablesOf(gScene), win));
  // Moved by 1.25 sides right and 0.5 down: beyond any particle's motion noise, inside
  // the reach of 1.5 sides.
  const int dx = 60, dy = 24;
  gScene.paint(100 + dx, 80 + dy, kSide, 7);
  REQUIRE(gCue.search(tablesOf(gScene), win));
  CHECK(gCue.peak() > 0.95f);
  const Box p = gCue.peakBox();
  const float cell = kSide / static_cast<float>(CorrelationCue::kCells);
  CHECK(std::abs(p.x - (100.f + dx)) <= cell);
  CHECK(std::abs(p.y - (80.f + dy)) <= cell);
  CHECK(p.w == win.w);
  // The map: the peak at the moved centre, much less one side away, nothing off the map.
  const float cu = 100.f + dx + 0.5f * kSide, cv = 80.f + dy + 0.5f * kSide;
  CHECK(gCue.at(cu, cv) == Approx(gCue.peak()).margin(0.1f));
  CHECK(gCue.at(cu - kSide, cv) < 0.5f);
  CHECK(gCue.at(cu + 3.f * kSide, cv) == CorrelationCue::kNoResponse);
}

TEST_CASE("CorrelationCue does not find a target that moved beyond its reach",
          "[core][correlation]") {
  constexpr int kSide = 40;
  gScene.paint(40, 60, kSide, 11);
  const Box win{40.f, 60.f, kSide, kSide};
  REQUIRE(gCue.reset(tablesOf(gScene), win));
  gScene.paint(40 + 3 * kSide, 60, kSide, 11);  // 3 sides away: the reach is 1.5
  REQUIRE(gCue.search(tablesOf(gScene), win));
  CHECK(gCue.peak() < 0.5f);  // the flat background and the texture's edge only
}

TEST_CASE("CorrelationCue is invariant to brightness and contrast", "[core][correlation]") {
  constexpr int kSide = 36;
  gScene.paint(120, 100, kSide, 3);
  const Box win{120.f, 100.f, kSide, kSide};
  REQUIRE(gCue.reset(tablesOf(gScene), win));
  // Same texture, half the contrast and brighter: the NCC does not change.
  for (Rgb8& p : gScene.rgb) {
    const uint8_t g = static_cast<uint8_t>(60 + p.r / 2);
    p = Rgb8{g, g, g};
  }
  REQUIRE(gCue.search(tablesOf(gScene), win));
  CHECK(gCue.peak() > 0.95f);
  CHECK(std::abs(gCue.peakBox().x - win.x) < 1.f);
}

TEST_CASE("CorrelationCue refuses a flat window and one off the tables", "[core][correlation]") {
  gScene.paint(0, 0, 0, 1);  // all background
  CHECK_FALSE(gCue.reset(tablesOf(gScene), Box{50.f, 50.f, 40.f, 40.f}));
  CHECK_FALSE(gCue.ready());
  CHECK_FALSE(gCue.search(tablesOf(gScene), Box{50.f, 50.f, 40.f, 40.f}));
  gScene.paint(50, 50, 40, 5);
  // The tables cover only a region that does not hold the whole window.
  CHECK_FALSE(gCue.reset(tablesOf(gScene, PixelRect{0, 0, 70, 70}), Box{50.f, 50.f, 40.f, 40.f}));
  // With the whole window, but the search's region cut by the tables: offsets whose
  // patch leaves them answer kNoResponse, the rest are matched.
  REQUIRE(gCue.reset(tablesOf(gScene), Box{50.f, 50.f, 40.f, 40.f}));
  REQUIRE(gCue.search(tablesOf(gScene, PixelRect{40, 40, 100, 100}), Box{50.f, 50.f, 40.f, 40.f}));
  CHECK(gCue.peak() > 0.95f);
  CHECK(gCue.at(70.f - 30.f, 70.f) == CorrelationCue::kNoResponse);
}

TEST_CASE("CorrelationCue learns a changed appearance at its rate", "[core][correlation]") {
  constexpr int kSide = 40;
  const Box win{100.f, 100.f, kSide, kSide};
  gScene.paint(100, 100, kSide, 21);
  REQUIRE(gCue.reset(tablesOf(gScene), win));
  gScene.paint(100, 100, kSide, 22);  // another texture in the same place
  REQUIRE(gCue.search(tablesOf(gScene), win));
  const float before = gCue.at(120.f, 120.f);
  CHECK(before < 0.6f);
  gCue.learn(tablesOf(gScene), win, 0.f);  // rate 0: nothing changes
  REQUIRE(gCue.search(tablesOf(gScene), win));
  CHECK(gCue.at(120.f, 120.f) == before);
  for (int i = 0; i < 10; ++i) gCue.learn(tablesOf(gScene), win, 0.3f);
  REQUIRE(gCue.search(tablesOf(gScene), win));
  CHECK(gCue.at(120.f, 120.f) > 0.95f);
}
