// The Kinect v1 depth model over the rasteriser's true depth: true depth -> raw
// disparity (1/8 px steps, KinectDepth.hpp) + Gaussian disparity noise -> rounded -> mm,
// no reading outside [minDepthMm, maxDepthMm] or in the projector's shadow; the colour
// sensor's noise and the lighting gain; and the edge dropout along the target's
// silhouette. Noise comes from tables drawn at construction, so a frame is the same
// bytes for a seed on every architecture.
#include <cmath>

#include "SynthCommon.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

using synth::kBackgroundOwner;
using synth::kPi;
using synth::splitmix64;

void SyntheticSource::applyDepthModel(FrameSlot& out, uint32_t frameSeed) {
  const int w = _spec.width, h = _spec.height;
  // Brightness for this frame, in 1/256 steps.
  const float tS = static_cast<float>(out.index) / _spec.fps;
  float gain = 1.f;
  if (_spec.lightAmplitude != 0.f && _spec.lightPeriodS > 0.f)
    gain += _spec.lightAmplitude * std::sin(2.f * kPi * tS / _spec.lightPeriodS);
  if (_spec.lightStepFrame >= 0 && out.index >= _spec.lightStepFrame) gain *= _spec.lightStepGain;
  if (gain < 0.f) gain = 0.f;
  const int gain256 = static_cast<int>(gain * 256.f + 0.5f);
  const float fb = _k.fx * _spec.baselineMm;
  const float sigma = _spec.disparityNoiseRaw;
  const float minZ = _spec.minDepthMm, maxZ = _spec.maxDepthMm;
  const bool shadows = _spec.shadows;
  constexpr float kB = static_cast<float>(kinect::kRawToInvMetresB);
  constexpr float kInvA = static_cast<float>(1.0 / kinect::kRawToInvMetresA);
  constexpr float kNoDepthF = static_cast<float>(kinect::kRawNoDepth);

  for (int v = 0; v < h; ++v) {
    // Noise comes from fixed tables at a random offset per row: one draw per row keeps
    // the per-pixel loops branch-light (colour) and division-free on background runs.
    uint64_t rs = (static_cast<uint64_t>(frameSeed) << 32) ^
                  ((static_cast<uint64_t>(v) + 1) * 0x9E3779B97F4A7C15ull);
    const uint64_t rowDraw = splitmix64(rs);
    const int8_t* cn = _colourNoise + (rowDraw & (kColourNoiseLen / 2 - 1));
    const float* gn = _gaussian + ((rowDraw >> 32) & 2047u);
    Rgb8* rgb = out.rgb.data() + v * w;
    uint8_t* bytes = reinterpret_cast<uint8_t*>(rgb);
    if (gain256 == 256) {
      // Noise only (most scenes): 16-bit lanes, no multiply.
      for (int i = 0; i < 3 * w; ++i) {
        const int16_t val = static_cast<int16_t>(bytes[i] + cn[i]);
        bytes[i] = static_cast<uint8_t>(val < 0 ? 0 : (val > 255 ? 255 : val));
      }
    } else {
      // Gain in 1/128 steps, at most 2x, so the product fits 16-bit lanes (255 * 256).
      const uint16_t g128 = static_cast<uint16_t>(gain256 >= 512 ? 256 : (gain256 + 1) / 2);
      for (int i = 0; i < 3 * w; ++i) {
        const uint16_t scaled = static_cast<uint16_t>((bytes[i] * g128 + 64u) >> 7);
        const int16_t val = static_cast<int16_t>(scaled + cn[i]);
        bytes[i] = static_cast<uint8_t>(val < 0 ? 0 : (val > 255 ? 255 : val));
      }
    }
    uint16_t* dmm = out.depthMm.data() + v * w;
    const float* z = _zMm + v * w;
    // Pass 1 (vectorised: restrict pointers, float clamps, int32 out): true depth ->
    // noisy raw disparity (1/8 px steps); out of range -> "no reading".
    {
      const float* __restrict zr = z;
      const float* __restrict g = gn;
      float* __restrict inv = _rowInvZ;
      int32_t* __restrict rawOut = _rowRaw;
      for (int u = 0; u < w; ++u) {
        const float zz = zr[u];
        const float iv = 1.f / zz;
        inv[u] = iv;
        float raw = (1000.f * iv - kB) * kInvA + sigma * g[u] + 0.5f;
        raw = raw < 0.f ? 0.f : raw;
        raw = raw > kNoDepthF ? kNoDepthF : raw;
        const int32_t q = static_cast<int32_t>(raw);
        rawOut[u] = (zz >= minZ && zz <= maxZ) ? q : kinect::kRawNoDepth;
      }
    }
    if (_backdropDepthMm) {
      backdropDepthRow(v, dmm);
      continue;
    }
    // Pass 2, right to left: a pixel is in the projector's shadow when a nearer pixel to
    // its right lands at or left of it in the projector's image.
    float runMin = 1e30f;
    for (int u = w - 1; u >= 0; --u) {
      const float up = static_cast<float>(u) - fb * _rowInvZ[u];  // column in the projector image
      const bool shadowed = shadows && up > runMin;
      runMin = up < runMin ? up : runMin;
      dmm[u] = shadowed ? 0 : _rawToMm.mm[_rowRaw[u]];
    }
  }
}

// The depth model's pass 2 over a still (pass 1 made _rowInvZ and _rowRaw): the still's
// pixels keep their real reading, which already has its own noise and shadows, unless an
// object's pixel casts the projector's shadow on them; an object's pixel is shadowed by
// anything nearer to its right, object or real surface.
void SyntheticSource::backdropDepthRow(int v, uint16_t* dmm) {
  const int w = _spec.width;
  const float fb = _k.fx * _spec.baselineMm;
  const uint16_t* still = _backdropDepthMm + v * w;
  const uint8_t* own = _owner + v * w;
  float runMinAll = 1e30f, runMinObjects = 1e30f;
  for (int u = w - 1; u >= 0; --u) {
    const float up = static_cast<float>(u) - fb * _rowInvZ[u];  // column in the projector image
    const bool object = own[u] != kBackgroundOwner;
    if (object) {
      dmm[u] = _spec.shadows && up > runMinAll ? 0 : _rawToMm.mm[_rowRaw[u]];
      runMinObjects = up < runMinObjects ? up : runMinObjects;
    } else {
      dmm[u] = _spec.shadows && up > runMinObjects ? 0 : still[u];
    }
    runMinAll = up < runMinAll ? up : runMinAll;
  }
}

void SyntheticSource::applyEdgeHoles(FrameSlot& out, uint32_t frameSeed) {
  // Only pixels within the band of the target's projected box can be near its silhouette.
  const Box& b = _truth.projectedBox;
  if (b.empty() || _truth.projectedPixels == 0) return;
  const int w = _spec.width, h = _spec.height;
  const int band =
      _spec.edgeHoleBandPx < 1 ? 1 : (_spec.edgeHoleBandPx > 8 ? 8 : _spec.edgeHoleBandPx);
  const uint8_t target = static_cast<uint8_t>(_spec.targetIndex);
  int u0 = static_cast<int>(b.x) - band, v0 = static_cast<int>(b.y) - band;
  int u1 = static_cast<int>(std::ceil(b.x + b.w)) + band;
  int v1 = static_cast<int>(std::ceil(b.y + b.h)) + band;
  u0 = u0 < 0 ? 0 : u0;
  v0 = v0 < 0 ? 0 : v0;
  u1 = u1 > w ? w : u1;
  v1 = v1 > h ? h : v1;
  // Drop thresholds per distance, in 1/2^24 steps.
  uint32_t threshold[9] = {};
  for (int d = 1; d <= band; ++d)
    threshold[d] =
        static_cast<uint32_t>(_spec.edgeHoleProbability * static_cast<float>(band + 1 - d) /
                              static_cast<float>(band) * 16777216.f);
  uint16_t* depth = out.depthMm.data();
  for (int v = v0; v < v1; ++v) {
    for (int u = u0; u < u1; ++u) {
      const bool inside = _owner[v * w + u] == target;
      // Chebyshev distance to the other side of the silhouette: the first ring reaching it.
      int dist = 0;
      for (int r = 1; r <= band && dist == 0; ++r) {
        for (int dv = -r; dv <= r && dist == 0; ++dv) {
          const int vv = v + dv;
          if (vv < 0 || vv >= h) continue;
          const int step = (dv == -r || dv == r) ? 1 : 2 * r;
          for (int du = -r; du <= r; du += step) {
            const int uu = u + du;
            if (uu < 0 || uu >= w) continue;
            if ((_owner[vv * w + uu] == target) != inside) {
              dist = r;
              break;
            }
          }
        }
      }
      if (dist == 0) continue;
      uint64_t s = (static_cast<uint64_t>(frameSeed) << 32) ^
                   (static_cast<uint64_t>(v * w + u) * 0xD1B54A32D192ED03ull);
      if (static_cast<uint32_t>(splitmix64(s) >> 40) < threshold[dist]) depth[v * w + u] = 0;
    }
  }
}

}  // namespace cuetrack
