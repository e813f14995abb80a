#include "cuetrack/core/cues/HogCnFeatures.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/cues/CellSampling.hpp"
#include "cuetrack/core/cues/ColourNames.hpp"

namespace cuetrack {

namespace {
constexpr float kInv255 = 1.f / 255.f;
constexpr float kClip = 0.2f;            // fHOG's clipping of a normalised bin
constexpr float kTextureGain = 0.2357f;  // fHOG's texture scale (1 / sqrt(18))
constexpr float kEnergyEps = 1e-4f;      // a flat block: no division by ~0
constexpr int kN = kFftSide;
constexpr int S = HogCnFeatures::kSamples;
constexpr int kBins = HogCnFeatures::kOrientations;

uint8_t toByte(float v) {  // v in [0, 255] (a convex mix of bytes), rounded
  return static_cast<uint8_t>(static_cast<int>(v + 0.5f));
}
static_assert(kBins == cellSampling::kOrientations, "the shared orientation bins");
using cellSampling::Tap;
using cellSampling::tapAt;
}  // namespace

bool HogCnFeatures::extract(const RgbView& rgb, const Box& win, float (*out)[kFftSize]) {
  if (rgb.empty() || !(win.w > 0.f) || !(win.h > 0.f)) return false;
  // Far outside the image the taps clamp anyway; the bound keeps floorToInt in range.
  const float lim = 4.f * static_cast<float>(kMaxImageWidth + kMaxImageHeight);
  if (!(win.x > -lim && win.y > -lim && win.x + win.w < lim && win.y + win.h < lim)) return false;
  const float sx = win.w / static_cast<float>(S), sy = win.h / static_cast<float>(S);
  Tap cols[S];
  for (int j = 0; j < S; ++j)
    cols[j] = tapAt(win.x + (static_cast<float>(j) + 0.5f) * sx - 0.5f, rgb.width);
  // Samples: colour, bilinear, and its gray level.
  for (int i = 0; i < S; ++i) {
    const Tap ty = tapAt(win.y + (static_cast<float>(i) + 0.5f) * sy - 0.5f, rgb.height);
    const Rgb8* r0 = rgb.row(ty.i0);
    const Rgb8* r1 = rgb.row(ty.i1);
    const float fy = ty.f, gy = 1.f - ty.f;
    for (int j = 0; j < S; ++j) {
      const Tap& tx = cols[j];
      const float fx = tx.f, gx = 1.f - tx.f;
      const Rgb8 a = r0[tx.i0], b = r0[tx.i1], c = r1[tx.i0], d = r1[tx.i1];
      const float wa = gx * gy, wb = fx * gy, wc = gx * fy, wd = fx * fy;
      const float R = wa * static_cast<float>(a.r) + wb * static_cast<float>(b.r) +
                      wc * static_cast<float>(c.r) + wd * static_cast<float>(d.r);
      const float G = wa * static_cast<float>(a.g) + wb * static_cast<float>(b.g) +
                      wc * static_cast<float>(c.g) + wd * static_cast<float>(d.g);
      const float B = wa * static_cast<float>(a.b) + wb * static_cast<float>(b.b) +
                      wc * static_cast<float>(c.b) + wd * static_cast<float>(d.b);
      _rgb[i * S + j] = Rgb8{toByte(R), toByte(G), toByte(B)};
      _gray[i * S + j] = (0.299f * R + 0.587f * G + 0.114f * B) * kInv255;
    }
  }
  // Gradients (central differences, one-sided at the border): magnitude and signed
  // orientation bin, from the boundaries it is past (no angle, no branch).
  for (int i = 0; i < S; ++i) {
    const float* up = _gray + (i > 0 ? i - 1 : i) * S;
    const float* dn = _gray + (i < S - 1 ? i + 1 : i) * S;
    const float* row = _gray + i * S;
    for (int j = 0; j < S; ++j) {
      const int jl = j > 0 ? j - 1 : j, jr = j < S - 1 ? j + 1 : j;
      const float dx = row[jr] - row[jl], dy = dn[j] - up[j];
      const int k = i * S + j;
      _mag[k] = fmath::sqrtf(dx * dx + dy * dy);
      _bin[k] = cellSampling::signedBin(dx, dy);
    }
  }
  // Cells: orientation histograms, colour names and gray, averaged.
  constexpr float perCell = 1.f / static_cast<float>(kCellPx * kCellPx);
  constexpr float nameScale = perCell * colourNames::kStep;
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      const int c = y * kN + x;
      float* h = _hist[c];
      for (int o = 0; o < 2 * kBins; ++o) h[o] = 0.f;
      int names[colourNames::kNames] = {};
      float gsum = 0.f;
      for (int v = 0; v < kCellPx; ++v) {
        const int k0 = (y * kCellPx + v) * S + x * kCellPx;
        for (int u = 0; u < kCellPx; ++u) {
          const int k = k0 + u;
          h[_bin[k]] += _mag[k];
          gsum += _gray[k];
          const Rgb8 p = _rgb[k];
          const int8_t* row = colourNames::kTable[colourNames::rowOf(p.r, p.g, p.b)];
          for (int n = 0; n < colourNames::kNames; ++n) names[n] += row[n];
        }
      }
      for (int n = 0; n < colourNames::kNames; ++n)
        out[kNameChannel + n][c] = static_cast<float>(names[n]) * nameScale;
      out[kGrayChannel][c] = gsum * perCell - 0.5f;
      float e = 0.f;
      for (int o = 0; o < kBins; ++o) {
        const float u = h[o] + h[o + kBins];
        e += u * u;
      }
      _energy[c] = e;
    }
  }
  // The inverse norm of the 2 x 2 block whose top-left cell is (x, y), clamped at the
  // grid's edge.
  for (int y = 0; y < kN; ++y) {
    const int y1 = y < kN - 1 ? y + 1 : y;
    for (int x = 0; x < kN; ++x) {
      const int x1 = x < kN - 1 ? x + 1 : x;
      const float e =
          _energy[y * kN + x] + _energy[y * kN + x1] + _energy[y1 * kN + x] + _energy[y1 * kN + x1];
      _blockInv[y * kN + x] = 1.f / fmath::sqrtf(e + kEnergyEps);
    }
  }
  // Each cell normalised by its four blocks, clipped: the four summed and halved for the
  // orientations; for the texture channels, each block's sum over the orientations.
  for (int y = 0; y < kN; ++y) {
    const int y0 = y > 0 ? y - 1 : y;
    for (int x = 0; x < kN; ++x) {
      const int x0 = x > 0 ? x - 1 : x;
      const float inv[4] = {_blockInv[y0 * kN + x0], _blockInv[y0 * kN + x], _blockInv[y * kN + x0],
                            _blockInv[y * kN + x]};
      const int c = y * kN + x;
      const float* h = _hist[c];
      float texture[4] = {0.f, 0.f, 0.f, 0.f};
      for (int o = 0; o < 2 * kBins; ++o) {
        float v = 0.f;
        for (int b = 0; b < 4; ++b) {
          const float n = h[o] * inv[b];
          const float clipped = n < kClip ? n : kClip;
          v += clipped;
          texture[b] += clipped;
        }
        out[kSignedChannel + o][c] = 0.5f * v;
      }
      for (int o = 0; o < kBins; ++o) {
        const float u = h[o] + h[o + kBins];
        float v = 0.f;
        for (int b = 0; b < 4; ++b) {
          const float n = u * inv[b];
          v += n < kClip ? n : kClip;
        }
        out[kUnsignedChannel + o][c] = 0.5f * v;
      }
      for (int b = 0; b < 4; ++b) out[kTextureChannel + b][c] = kTextureGain * texture[b];
    }
  }
  return true;
}

}  // namespace cuetrack
