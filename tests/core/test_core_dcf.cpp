// Fft and CorrelationFilter: the transform against its definition, and the filter
// finding a moved, grown or shrunk target, learning, and refusing what it cannot use.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/cues/CorrelationFilter.hpp"
#include "cuetrack/core/kernels/Fft.hpp"

using namespace cuetrack;

namespace {

float gRe[kFftSize], gIm[kFftSize], gA[kFftSize], gB[kFftSize];
float gAr[kFftSize], gAi[kFftSize], gBr[kFftSize], gBi[kFftSize];

void randomPlane(Rng& r, float* p) {
  for (int i = 0; i < kFftSize; ++i) p[i] = r.uniform() - 0.5f;
}

}  // namespace

TEST_CASE("Fft: the 2D transform is the DFT (transposed), and the inverse undoes it",
          "[core][dcf]") {
  Rng r(3);
  randomPlane(r, gRe);
  randomPlane(r, gIm);
  for (int i = 0; i < kFftSize; ++i) {
    gA[i] = gRe[i];
    gB[i] = gIm[i];
  }
  fft::forward2d(gRe, gIm);
  // Against the DFT's definition at a few frequencies, in double.
  for (const int k : {0, 1, 33, 100, 517, 1023}) {
    const int ky = k / kFftSide, kx = k % kFftSide;
    double sr = 0.0, si = 0.0;
    for (int y = 0; y < kFftSide; ++y)
      for (int x = 0; x < kFftSide; ++x) {
        const double a = -2.0 * M_PI * (ky * y + kx * x) / kFftSide;
        const int i = y * kFftSide + x;
        sr += gA[i] * std::cos(a) - gB[i] * std::sin(a);
        si += gA[i] * std::sin(a) + gB[i] * std::cos(a);
      }
    CHECK(gRe[kx * kFftSide + ky] == Approx(sr).margin(1e-4));
    CHECK(gIm[kx * kFftSide + ky] == Approx(si).margin(1e-4));
  }
  fft::inverse2d(gRe, gIm);
  for (int i = 0; i < kFftSize; ++i) {
    CHECK(gRe[i] == Approx(gA[i]).margin(1e-5));
    CHECK(gIm[i] == Approx(gB[i]).margin(1e-5));
  }
}

TEST_CASE("Fft: the batched 2D transform is the scalar reference's, bit for bit", "[core][dcf]") {
  // forward2d runs every column's butterflies as one loop over a row (vectorised); the
  // reference is transform1d along each column, then each row. Same operations, same
  // order: the same bits, on every ISA.
  Rng r(7);
  randomPlane(r, gRe);
  randomPlane(r, gIm);
  for (int i = 0; i < kFftSize; ++i) {
    gA[i] = gRe[i];
    gB[i] = gIm[i];
  }
  for (int c = 0; c < kFftSide; ++c) fft::transform1d(gA + c, gB + c, kFftSide, false);
  for (int row = 0; row < kFftSide; ++row)
    fft::transform1d(gA + row * kFftSide, gB + row * kFftSide, 1, false);
  fft::forward2d(gRe, gIm);
  int same = 0;
  for (int y = 0; y < kFftSide; ++y)
    for (int x = 0; x < kFftSide; ++x)
      same += (gRe[x * kFftSide + y] == gA[y * kFftSide + x] &&
               gIm[x * kFftSide + y] == gB[y * kFftSide + x])
                  ? 1
                  : 0;
  CHECK(same == kFftSize);
}

TEST_CASE("Fft: two real planes at once give each one's transform", "[core][dcf]") {
  Rng r(5);
  randomPlane(r, gA);
  randomPlane(r, gB);
  fft::forwardRealPair(gA, gB, gAr, gAi, gBr, gBi);
  for (const float* plane : {gA, gB}) {
    for (int i = 0; i < kFftSize; ++i) {
      gRe[i] = plane[i];
      gIm[i] = 0.f;
    }
    fft::forward2d(gRe, gIm);
    const float* re = plane == gA ? gAr : gBr;
    const float* im = plane == gA ? gAi : gBi;
    for (int i = 0; i < kFftSize; ++i) {
      CHECK(re[i] == Approx(gRe[i]).margin(1e-4));
      CHECK(im[i] == Approx(gIm[i]).margin(1e-4));
    }
  }
}

namespace {

constexpr int W = 320, H = 240;

// A mid-gray background with faint noise (new each frame, as a camera's), and a target:
// a smooth texture (12 x 12 random colours, blended bilinearly) in a box of w x h px at
// (x, y), drawn at `scale` about its centre.
struct Scene {
  Rgb8 rgb[W * H];
  uint32_t frame = 0;
  void paint(float x, float y, float w, float h, float scale = 1.f, uint32_t seed = 11) {
    Rng bg(99 + frame++);
    for (Rgb8& p : rgb) {
      const uint8_t g = static_cast<uint8_t>(120 + bg.below(16));
      p = Rgb8{g, g, g};
    }
    Rng r(seed);
    float tex[12 * 12][3];
    for (auto& t : tex)
      for (float& c : t) c = static_cast<float>(r.below(256));
    const float cx = x + 0.5f * w, cy = y + 0.5f * h, sw = w * scale, sh = h * scale;
    for (int py = 0; py < H; ++py)
      for (int px = 0; px < W; ++px) {
        const float u = (static_cast<float>(px) + 0.5f - (cx - 0.5f * sw)) / sw;
        const float v = (static_cast<float>(py) + 0.5f - (cy - 0.5f * sh)) / sh;
        if (u < 0.f || v < 0.f || u >= 1.f || v >= 1.f) continue;
        const float fu = u * 11.f, fv = v * 11.f;
        const int iu = static_cast<int>(fu), iv = static_cast<int>(fv);
        const float au = fu - static_cast<float>(iu), av = fv - static_cast<float>(iv);
        uint8_t out[3];
        for (int c = 0; c < 3; ++c)
          out[c] = static_cast<uint8_t>((1.f - au) * (1.f - av) * tex[iv * 12 + iu][c] +
                                        au * (1.f - av) * tex[iv * 12 + iu + 1][c] +
                                        (1.f - au) * av * tex[(iv + 1) * 12 + iu][c] +
                                        au * av * tex[(iv + 1) * 12 + iu + 1][c]);
        rgb[py * W + px] = Rgb8{out[0], out[1], out[2]};
      }
  }
  RgbView view() const { return RgbView{rgb, W, H, W}; }
};

Scene gScene;
CorrelationFilter gFilter;  // large: static storage

}  // namespace

TEST_CASE("CorrelationFilter finds the target where it moved", "[core][dcf]") {
  const Box start{120.f, 90.f, 40.f, 32.f};
  gScene.paint(start.x, start.y, start.w, start.h);
  REQUIRE(gFilter.reset(gScene.view(), start));
  // On the frame it learnt: the peak at zero shift, near 1, standing out.
  REQUIRE(gFilter.search(gScene.view(), start, false));
  CHECK(gFilter.peakBox().x == Approx(start.x).margin(0.5));
  CHECK(gFilter.peak() > 0.8f);
  CHECK(gFilter.sharpness() > 10.f);
  CHECK(gFilter.at(start.x + 20.f, start.y + 16.f) == Approx(1.f).margin(0.05));
  // Moved by 0.6 of a side right and 0.4 down: found within a pixel.
  const float dx = 24.f, dy = 13.f;
  gScene.paint(start.x + dx, start.y + dy, start.w, start.h);
  REQUIRE(gFilter.search(gScene.view(), start, false));
  CHECK(gFilter.peakBox().x == Approx(start.x + dx).margin(1.0));
  CHECK(gFilter.peakBox().y == Approx(start.y + dy).margin(1.0));
  // Weaker than at zero shift: the cosine window fades the target towards its edge.
  CHECK(gFilter.peak() > 0.2f);
  // The response falls off away from the peak, and is not read outside the window.
  const Box p = gFilter.peakBox();
  CHECK(gFilter.at(p.x + 0.5f * p.w + 15.f, p.y + 0.5f * p.h) < 0.5f);
  CHECK(gFilter.at(p.x + 400.f, p.y) == CorrelationFilter::kNoResponse);
}

TEST_CASE("CorrelationFilter follows a target that grows or shrinks", "[core][dcf]") {
  const Box start{130.f, 95.f, 48.f, 40.f};
  gScene.paint(start.x, start.y, start.w, start.h);
  REQUIRE(gFilter.reset(gScene.view(), start));
  const float grown = tuning::dcf::kScaleStep;  // one step a frame
  gScene.paint(start.x, start.y, start.w, start.h, grown);
  REQUIRE(gFilter.search(gScene.view(), start, true));
  CHECK(gFilter.peakBox().w > start.w * 1.01f);
  gScene.paint(start.x, start.y, start.w, start.h, 1.f / grown);
  REQUIRE(gFilter.search(gScene.view(), start, true));
  CHECK(gFilter.peakBox().w < start.w / 1.01f);
  // At its own size, its own size.
  gScene.paint(start.x, start.y, start.w, start.h);
  REQUIRE(gFilter.search(gScene.view(), start, true));
  CHECK(gFilter.peakBox().w == start.w);
}

TEST_CASE("CorrelationFilter learns a new look and refuses what it cannot use", "[core][dcf]") {
  const Box start{120.f, 90.f, 40.f, 32.f};
  gScene.paint(start.x, start.y, start.w, start.h, 1.f, 11);
  REQUIRE(gFilter.reset(gScene.view(), start));
  gScene.paint(start.x, start.y, start.w, start.h, 1.f, 12);  // another texture
  REQUIRE(gFilter.search(gScene.view(), start, false));
  const float before = gFilter.peak();
  for (int i = 0; i < 10; ++i) gFilter.learn(gScene.view(), start, 0.2f);
  REQUIRE(gFilter.search(gScene.view(), start, false));
  CHECK(gFilter.peak() > before + 0.2f);
  // Nothing to learn from or search: an empty image or box.
  CorrelationFilter& f = gFilter;
  CHECK_FALSE(f.search(gScene.view(), Box{}, false));
  CHECK_FALSE(f.search(RgbView{}, start, false));
  CHECK_FALSE(f.reset(gScene.view(), Box{}));
  CHECK_FALSE(f.ready());
  CHECK_FALSE(f.search(gScene.view(), start, false));
  CHECK(f.at(140.f, 106.f) == CorrelationFilter::kNoResponse);
}

TEST_CASE("CorrelationFilter tracks a target of 3 x 3 px", "[core][dcf]") {
  const Box start{150.f, 100.f, 3.f, 3.f};
  gScene.paint(start.x, start.y, 3.f, 3.f);
  // A 3 px target's window is 7.5 px: upsampled to the grid.
  REQUIRE(gFilter.reset(gScene.view(), start));
  gScene.paint(start.x + 2.f, start.y + 1.f, 3.f, 3.f);
  REQUIRE(gFilter.search(gScene.view(), start, false));
  CHECK(gFilter.peakBox().x == Approx(start.x + 2.f).margin(0.75));
  CHECK(gFilter.peakBox().y == Approx(start.y + 1.f).margin(0.75));
}
