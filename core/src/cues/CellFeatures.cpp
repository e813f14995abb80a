#include "cuetrack/core/cues/CellFeatures.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/cues/CellSampling.hpp"

namespace cuetrack {

namespace {
constexpr float kInv255 = 1.f / 255.f;
constexpr float kClip = 0.2f;        // HOG's clipping of a normalised bin
constexpr float kEnergyEps = 1e-4f;  // a flat block: no division by ~0
constexpr int kN = kFftSide;
constexpr int S = CellFeatures::kSamples;
constexpr int kBins = CellFeatures::kOrientations;

// A histogram value normalised by each of its four blocks, clipped, summed, halved.
float normalised(float h, const float inv[4]) {
  float v = 0.f;
  for (int b = 0; b < 4; ++b) {
    const float n = h * inv[b];
    v += n < kClip ? n : kClip;
  }
  return 0.5f * v;
}

static_assert(kBins == cellSampling::kOrientations, "the shared orientation bins");
using cellSampling::Tap;
using cellSampling::tapAt;
}  // namespace

bool CellFeatures::extract(const RgbView& rgb, const Box& win, float (*out)[kFftSize]) {
  if (rgb.empty() || !(win.w > 0.f) || !(win.h > 0.f)) return false;
  // Far outside the image, the taps clamp anyway; the bound keeps floorToInt in range.
  const float lim = 4.f * static_cast<float>(kMaxImageWidth + kMaxImageHeight);
  if (!(win.x > -lim && win.y > -lim && win.x + win.w < lim && win.y + win.h < lim)) return false;
  const float sx = win.w / static_cast<float>(S), sy = win.h / static_cast<float>(S);
  Tap cols[S];
  for (int j = 0; j < S; ++j)
    cols[j] = tapAt(win.x + (static_cast<float>(j) + 0.5f) * sx - 0.5f, rgb.width);
  // Sample: gray and the two colour opponents, bilinear.
  for (int i = 0; i < S; ++i) {
    const Tap ty = tapAt(win.y + (static_cast<float>(i) + 0.5f) * sy - 0.5f, rgb.height);
    const Rgb8* r0 = rgb.row(ty.i0);
    const Rgb8* r1 = rgb.row(ty.i1);
    const float fy = ty.f, gy = 1.f - ty.f;
    float* g = _gray + i * S;
    float* ca = _ca + i * S;
    float* cb = _cb + i * S;
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
      g[j] = (0.299f * R + 0.587f * G + 0.114f * B) * kInv255;
      ca[j] = (R - G) * kInv255;
      cb[j] = (0.5f * (R + G) - B) * kInv255;
    }
  }
  gradients();
  cells(out);
  normalise(out);
  return true;
}

void CellFeatures::gradients() {
  // Gradients (central differences, one-sided at the border): magnitude and unsigned
  // orientation bin (the boundaries it is past, counted: no angle, no branch).
  for (int i = 0; i < S; ++i) {
    const float* up = _gray + (i > 0 ? i - 1 : i) * S;
    const float* dn = _gray + (i < S - 1 ? i + 1 : i) * S;
    const float* row = _gray + i * S;
    float* gx = _dx + i * S;
    float* gy = _dy + i * S;
    gx[0] = row[1] - row[0];
    for (int j = 1; j < S - 1; ++j) gx[j] = row[j + 1] - row[j - 1];
    gx[S - 1] = row[S - 1] - row[S - 2];
    for (int j = 0; j < S; ++j) gy[j] = dn[j] - up[j];
  }
  for (int k = 0; k < S * S; ++k) {
    const float dx = _dx[k], dy = _dy[k];
    _mag[k] = fmath::sqrtf(dx * dx + dy * dy);
    _bin[k] = cellSampling::signedBin(dx, dy);
  }
}

void CellFeatures::cells(float (*out)[kFftSize]) {
  // Cells: the orientation histograms, mean gray and colour.
  for (int c = 0; c < kFftSize; ++c)
    for (int o = 0; o < 2 * kBins; ++o) _hist[c][o] = 0.f;
  constexpr float perCell = 1.f / static_cast<float>(kCellPx * kCellPx);
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      const int c = y * kN + x;
      float gsum = 0.f, asum = 0.f, bsum = 0.f;
      for (int v = 0; v < kCellPx; ++v) {
        const int k0 = (y * kCellPx + v) * S + x * kCellPx;
        for (int u = 0; u < kCellPx; ++u) {
          const int k = k0 + u;
          gsum += _gray[k];
          asum += _ca[k];
          bsum += _cb[k];
          _hist[c][_bin[k]] += _mag[k];
        }
      }
      out[kGrayChannel][c] = gsum * perCell - 0.5f;
      out[kColourChannel][c] = asum * perCell;
      out[kColourChannel + 1][c] = bsum * perCell;
    }
  }
}

void CellFeatures::normalise(float (*out)[kFftSize]) {
  // Unsigned: a direction and its opposite together; the energy from them.
  for (int c = 0; c < kFftSize; ++c) {
    float e = 0.f;
    for (int o = 0; o < kBins; ++o) {
      const float u = _hist[c][o] + _hist[c][o + kBins];
      _unsigned[c][o] = u;
      e += u * u;
    }
    _energy[c] = e;
  }
  // The energy of the 2 x 2 block whose top-left cell is (x, y), clamped at the grid's
  // edge; each cell normalised by the four blocks that hold it, each normalised value
  // clipped, the four summed and halved.
  for (int y = 0; y < kN; ++y) {
    const int y1 = y < kN - 1 ? y + 1 : y;
    for (int x = 0; x < kN; ++x) {
      const int x1 = x < kN - 1 ? x + 1 : x;
      const float e =
          _energy[y * kN + x] + _energy[y * kN + x1] + _energy[y1 * kN + x] + _energy[y1 * kN + x1];
      _blockInv[y * kN + x] = 1.f / fmath::sqrtf(e + kEnergyEps);
    }
  }
  for (int y = 0; y < kN; ++y) {
    const int y0 = y > 0 ? y - 1 : y;
    for (int x = 0; x < kN; ++x) {
      const int x0 = x > 0 ? x - 1 : x;
      const float inv[4] = {_blockInv[y0 * kN + x0], _blockInv[y0 * kN + x], _blockInv[y * kN + x0],
                            _blockInv[y * kN + x]};
      const int c = y * kN + x;
      for (int o = 0; o < kBins; ++o)
        out[kUnsignedChannel + o][c] = normalised(_unsigned[c][o], inv);
      if (kSigned)
        for (int o = 0; o < 2 * kBins; ++o) out[o][c] = normalised(_hist[c][o], inv);
    }
  }
}

}  // namespace cuetrack
