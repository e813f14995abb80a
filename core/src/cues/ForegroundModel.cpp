#include "cuetrack/core/cues/ForegroundModel.hpp"

namespace cuetrack {

namespace {
constexpr int S = ForegroundModel::kSide;
constexpr int kN = kFftSide;
constexpr int kShift = 8 - 4;  // 256 levels to kBinsPerChannel bins
static_assert(ForegroundModel::kBinsPerChannel == (256 >> kShift), "bins per channel");
// The surround's margin: a ring this many samples wide around the box is neither
// target nor surround (the box's edge is rarely exact).
constexpr int kGapSamples = 2;
// A colour seen in neither region: neither target nor background.
constexpr float kUnseen = 0.5f;

int colourOf(Rgb8 p) {
  return (p.r >> kShift) +
         ForegroundModel::kBinsPerChannel *
             ((p.g >> kShift) + ForegroundModel::kBinsPerChannel * (p.b >> kShift));
}
}  // namespace

void ForegroundModel::histograms(const Rgb8* samples, const Rect& t, float* fg, float* bg) const {
  for (int c = 0; c < kColours; ++c) fg[c] = bg[c] = 0.f;
  int nf = 0, nb = 0;
  for (int y = 0; y < S; ++y) {
    const bool rowIn = y >= t.y0 && y < t.y1;
    const bool rowNear = y >= t.y0 - kGapSamples && y < t.y1 + kGapSamples;
    for (int x = 0; x < S; ++x) {
      const int c = colourOf(samples[y * S + x]);
      if (rowIn && x >= t.x0 && x < t.x1) {
        fg[c] += 1.f;
        ++nf;
      } else if (!(rowNear && x >= t.x0 - kGapSamples && x < t.x1 + kGapSamples)) {
        bg[c] += 1.f;
        ++nb;
      }
    }
  }
  const float f = nf > 0 ? 1.f / static_cast<float>(nf) : 0.f;
  const float b = nb > 0 ? 1.f / static_cast<float>(nb) : 0.f;
  for (int c = 0; c < kColours; ++c) {
    fg[c] *= f;
    bg[c] *= b;
  }
}

void ForegroundModel::reset(const Rgb8* samples, const Rect& target) {
  histograms(samples, target, _fg, _bg);
  _ready = true;
}

void ForegroundModel::learn(const Rgb8* samples, const Rect& target, float rate) {
  if (!_ready) return reset(samples, target);
  histograms(samples, target, _newFg, _newBg);
  const float keep = 1.f - rate;
  for (int c = 0; c < kColours; ++c) {
    _fg[c] = keep * _fg[c] + rate * _newFg[c];
    _bg[c] = keep * _bg[c] + rate * _newBg[c];
  }
}

void ForegroundModel::likelihood(const Rgb8* samples, float* map) const {
  for (int i = 0; i < S * S; ++i) {
    const int c = colourOf(samples[i]);
    const float sum = _fg[c] + _bg[c];
    map[i] = sum > 0.f ? _fg[c] / sum : kUnseen;
  }
}

void ForegroundModel::cellMeans(const float* map, float* cells) {
  constexpr float perCell = 1.f / static_cast<float>(kCellPx * kCellPx);
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      float s = 0.f;
      for (int v = 0; v < kCellPx; ++v)
        for (int u = 0; u < kCellPx; ++u) s += map[(y * kCellPx + v) * S + x * kCellPx + u];
      cells[y * kN + x] = s * perCell;
    }
}

}  // namespace cuetrack
