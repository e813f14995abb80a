#include "cuetrack/core/cues/CorrelationFilter.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

namespace {
constexpr int kN = kFftSide;
constexpr int kHalf = kFftSide / 2;
using tuning::dcf::kLambda;
using tuning::dcf::kScalePenalty;
using tuning::dcf::kScaleStep;

// b scaled by f about its centre.
Box scaledAbout(const Box& b, float f) {
  const float w = b.w * f, h = b.h * f;
  return Box{b.x + 0.5f * (b.w - w), b.y + 0.5f * (b.h - h), w, h};
}
// Cell index i as a signed shift in (-kHalf, kHalf].
int shiftOf(int i) {
  return i > kHalf ? i - kN : i;
}
// The parabola's vertex through (-1, l), (0, c), (1, r), within half a cell.
float vertex(float l, float c, float r) {
  const float d = l - 2.f * c + r;
  if (!(d < 0.f)) return 0.f;
  return fmath::clampf(0.5f * (l - r) / d, -0.5f, 0.5f);
}
}  // namespace

CorrelationFilter::CorrelationFilter() {
  // Hann window, periodic; the label a Gaussian of the shift, wrapped, peaked at 0.
  float hann[kN];
  for (int i = 0; i < kN; ++i) hann[i] = 0.5f * (1.f - fft::cosTurn(i));
  constexpr float sigma =
      tuning::dcf::kLabelSigma * static_cast<float>(kN) / CorrelationFilter::kPadding;
  constexpr float g = -0.5f / (sigma * sigma);
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      _cosine[y * kN + x] = hann[y] * hann[x];
      const float dy = static_cast<float>(shiftOf(y)), dx = static_cast<float>(shiftOf(x));
      _yRe[y * kN + x] = fmath::fastExp(g * (dx * dx + dy * dy));
      _yIm[y * kN + x] = 0.f;
    }
  }
  fft::forward2d(_yRe, _yIm);
}

bool CorrelationFilter::transformed(const RgbView& rgb, const Box& target) {
  if (!_features.extract(rgb, scaledAbout(target, kPadding), _x)) return false;
  for (int l = 0; l < kChannels; ++l)
    for (int i = 0; i < kFftSize; ++i) _x[l][i] *= _cosine[i];
  static_assert(kChannels % 2 == 0, "channels are transformed in pairs");
  for (int l = 0; l < kChannels; l += 2)
    fft::forwardRealPair(_x[l], _x[l + 1], _zRe[l], _zIm[l], _zRe[l + 1], _zIm[l + 1]);
  return true;
}

bool CorrelationFilter::reset(const RgbView& rgb, const Box& target) {
  _ready = false;
  _searched = false;
  _peak = kNoResponse;
  if (target.empty() || !transformed(rgb, target)) return false;
  for (int i = 0; i < kFftSize; ++i) _b[i] = 0.f;
  for (int l = 0; l < kChannels; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      const float xr = _zRe[l][i], xi = _zIm[l][i];
      _aRe[l][i] = xr * _yRe[i] + xi * _yIm[i];  // conj(X) Y
      _aIm[l][i] = xr * _yIm[i] - xi * _yRe[i];
      _b[i] += xr * xr + xi * xi;
    }
  }
  _ready = true;
  return true;
}

void CorrelationFilter::learn(const RgbView& rgb, const Box& target, float rate) {
  if (!_ready || target.empty() || !transformed(rgb, target)) return;
  const float keep = 1.f - rate;
  for (int i = 0; i < kFftSize; ++i) _b[i] *= keep;
  for (int l = 0; l < kChannels; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      const float xr = _zRe[l][i], xi = _zIm[l][i];
      _aRe[l][i] = keep * _aRe[l][i] + rate * (xr * _yRe[i] + xi * _yIm[i]);
      _aIm[l][i] = keep * _aIm[l][i] + rate * (xr * _yIm[i] - xi * _yRe[i]);
      _b[i] += rate * (xr * xr + xi * xi);
    }
  }
}

void CorrelationFilter::respond(float* map, float* peak, int* peakAt) {
  float* re = map;
  float* im = _respIm;
  for (int i = 0; i < kFftSize; ++i) re[i] = im[i] = 0.f;
  for (int l = 0; l < kChannels; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      const float ar = _aRe[l][i], ai = _aIm[l][i], zr = _zRe[l][i], zi = _zIm[l][i];
      re[i] += ar * zr - ai * zi;
      im[i] += ar * zi + ai * zr;
    }
  }
  for (int i = 0; i < kFftSize; ++i) {
    const float inv = 1.f / (_b[i] + kLambda);
    re[i] *= inv;
    im[i] *= inv;
  }
  fft::inverse2d(re, im);
  int best = 0;
  for (int i = 1; i < kFftSize; ++i)
    if (re[i] > re[best]) best = i;
  *peak = re[best];
  *peakAt = best;
}

bool CorrelationFilter::search(const RgbView& rgb, const Box& around, bool scales) {
  _searched = false;
  _peak = kNoResponse;
  if (!_ready || around.empty()) return false;
  float bestScore = 0.f;
  int bestAt = -1;
  Box bestBox{};
  const float factors[kScales] = {1.f, 1.f / kScaleStep, kScaleStep};
  const int tries = scales ? kScales : 1;
  for (int s = 0; s < tries; ++s) {
    const Box b = s == 0 ? around : scaledAbout(around, factors[s]);
    if (!transformed(rgb, b)) return false;
    float p = 0.f;
    int at = 0;
    respond(s == 0 ? _map : _tryMap, &p, &at);
    const float score = s == 0 ? p : p * kScalePenalty;
    if (bestAt >= 0 && !(score > bestScore)) continue;
    if (s != 0)
      for (int i = 0; i < kFftSize; ++i) _map[i] = _tryMap[i];
    bestScore = score;
    bestAt = at;
    bestBox = b;
    _peak = p;
  }
  _cellW = bestBox.w * kPadding / static_cast<float>(kN);
  _cellH = bestBox.h * kPadding / static_cast<float>(kN);
  _cx = bestBox.x + 0.5f * bestBox.w;
  _cy = bestBox.y + 0.5f * bestBox.h;
  // Sub-cell peak; the peak to sidelobe ratio over the whole map.
  const int py = bestAt / kN, px = bestAt % kN;
  const float* m = _map;
  const float fx = vertex(m[py * kN + ((px + kN - 1) & (kN - 1))], m[bestAt],
                          m[py * kN + ((px + 1) & (kN - 1))]);
  const float fy = vertex(m[((py + kN - 1) & (kN - 1)) * kN + px], m[bestAt],
                          m[((py + 1) & (kN - 1)) * kN + px]);
  const float sx = static_cast<float>(shiftOf(px)) + fx, sy = static_cast<float>(shiftOf(py)) + fy;
  _peakBox = Box{bestBox.x + sx * _cellW, bestBox.y + sy * _cellH, bestBox.w, bestBox.h};
  float mean = 0.f;
  for (int i = 0; i < kFftSize; ++i) mean += m[i];
  mean /= static_cast<float>(kFftSize);
  float var = 0.f;
  for (int i = 0; i < kFftSize; ++i) var += (m[i] - mean) * (m[i] - mean);
  var /= static_cast<float>(kFftSize);
  _psr = var > 0.f ? (_peak - mean) / fmath::sqrtf(var) : 0.f;
  _searched = true;
  return true;
}

float CorrelationFilter::at(float u, float v) const {
  if (!_searched || !(_peak > 0.f)) return kNoResponse;
  const float fx = (u - _cx) / _cellW, fy = (v - _cy) / _cellH;
  // Within the window's shifts (or NaN) before the conversion to int.
  constexpr float lim = static_cast<float>(kHalf - 1);
  if (!(fx > -lim && fx < lim && fy > -lim && fy < lim)) return kNoResponse;
  const int x0 = fmath::floorToInt(fx), y0 = fmath::floorToInt(fy);
  const float ax = fx - static_cast<float>(x0), ay = fy - static_cast<float>(y0);
  const int xa = x0 & (kN - 1), xb = (x0 + 1) & (kN - 1);
  const int ya = y0 & (kN - 1), yb = (y0 + 1) & (kN - 1);
  const float* m = _map;
  const float r = (1.f - ay) * ((1.f - ax) * m[ya * kN + xa] + ax * m[ya * kN + xb]) +
                  ay * ((1.f - ax) * m[yb * kN + xa] + ax * m[yb * kN + xb]);
  return r / _peak;
}

}  // namespace cuetrack
