// A small synthetic RGB-D scene for the tracker tests: a textured square moving
// over a textured background, nearer than it. No dependency beyond core.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Rng.hpp"

namespace cuetrack::test {

// Side: the square's side [px] (48 in most tests; a few px for the small-target test).
template <int Side>
class MovingSquareOf {
 public:
  static constexpr int kW = 320, kH = 240, kSide = Side;
  static constexpr int kTex = 64;

  explicit MovingSquareOf(uint32_t seed = 1) {
    Rng r(seed);
    for (int i = 0; i < kTex * kTex; ++i) {
      const int b = ((i % kTex) / 8 + (i / kTex) / 8) % 3;
      _bg[i] = Rgb8{static_cast<uint8_t>(90 + 40 * b + r.below(20)),
                    static_cast<uint8_t>(110 + r.below(30)), static_cast<uint8_t>(80 + 30 * b)};
    }
    for (int i = 0; i < kSide * kSide; ++i) {
      const int x = i % kSide, y = i / kSide;
      // A 4 x 4 checker with a yellow centre (cells of 12 px and 18..30 at side 48).
      const bool q = ((4 * x / kSide) + (4 * y / kSide)) % 2 == 0;
      _obj[i] = q ? Rgb8{220, 60, 40} : Rgb8{40, 70, 200};
      const int c0 = 3 * kSide / 8, c1 = 5 * kSide / 8;
      if (x > c0 && x < c1 && y > c0 && y < c1) _obj[i] = Rgb8{240, 230, 60};
    }
  }

  // Object position at frame t [px, top-left]: 3 px a frame across and a triangle wave
  // of +-30 px up and down at side 48, both in proportion to the side.
  void position(int t, float* x, float* y) const {
    constexpr float s = static_cast<float>(kSide) / 48.f;  // exactly 1 at side 48
    *x = 40.f + 3.f * s * static_cast<float>(t);
    // (No libm: the scene must be the same bits on every platform.)
    const int p = t % 52;
    *y = 80.f +
         30.f * s *
             (p < 26 ? static_cast<float>(p) / 13.f - 1.f : 3.f - static_cast<float>(p) / 13.f);
  }
  Box truth(int t) const {
    float x, y;
    position(t, &x, &y);
    return Box{x, y, static_cast<float>(kSide), static_cast<float>(kSide)};
  }

  Frame render(int t, bool withDepth) {
    float fx, fy;
    position(t, &fx, &fy);
    const int ox = static_cast<int>(fx + 0.5f), oy = static_cast<int>(fy + 0.5f);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const int i = y * kW + x;
        const int u = x - ox, v = y - oy;
        const bool in = u >= 0 && v >= 0 && u < kSide && v < kSide;
        _rgb[i] = in ? _obj[v * kSide + u] : _bg[(y % kTex) * kTex + (x % kTex)];
        _depth[i] = in ? 1500 : static_cast<uint16_t>(3000 + (x % 7));
        if (!in && (x * 7 + y * 3) % 23 == 0) _depth[i] = 0;  // a few holes
      }
    Frame f;
    f.rgb = RgbView{_rgb, kW, kH, kW};
    if (withDepth) f.depthMm = DepthView{_depth, kW, kH, kW};
    f.timeUs = static_cast<uint64_t>(t) * 33333u;
    f.intrinsics = CameraIntrinsics{260.f, 260.f, 160.f, 120.f};
    return f;
  }

 private:
  Rgb8 _bg[kTex * kTex];
  Rgb8 _obj[kSide * kSide];
  Rgb8 _rgb[kW * kH];
  uint16_t _depth[kW * kH];
};

using MovingSquare = MovingSquareOf<48>;

}  // namespace cuetrack::test
