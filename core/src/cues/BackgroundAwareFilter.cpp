#include "cuetrack/core/cues/BackgroundAwareFilter.hpp"

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack {

namespace {
constexpr int kN = kFftSide;
constexpr int kHalf = kFftSide / 2;
constexpr int K = BackgroundAwareFilter::kChannels;
constexpr float kT = static_cast<float>(kFftSize);
// BACF's ADMM (BACF_optimized.m): 2 iterations, mu from 1 growing tenfold, lambda 0.01.
// Its mu multiplies T (its g-step has B = S_xx + T mu over unnormalised transforms, as
// ours); lambda is relative to mu T, so it is the same number here.
constexpr int kIterations = 2;
constexpr float kMu0 = 1.f * kT;
constexpr float kMuGrowth = 10.f;
constexpr float kMuMax = 1e4f * kT;
constexpr float kLambda = 0.01f;
// The mask: a cell of the box whose samples' mean likelihood of being target is below
// this is background; under kMinMaskShare of the box left, the whole box (CSR-DCF's
// fallback: a target of its background's colours).
constexpr float kMaskLikelihood = 0.5f;
constexpr float kMinMaskShare = 0.25f;
// The label's spread: 1/16 of the target's side in cells (BACF's output_sigma_factor).
constexpr float kLabelSigmaCells = static_cast<float>(kN) / BackgroundAwareFilter::kPadding / 16.f;

int shiftOf(int i) {  // cell index as a signed shift in (-kHalf, kHalf]
  return i > kHalf ? i - kN : i;
}
float vertex(float l, float c, float r) {  // the parabola's vertex, within half a cell
  const float d = l - 2.f * c + r;
  if (!(d < 0.f)) return 0.f;
  return fmath::clampf(0.5f * (l - r) / d, -0.5f, 0.5f);
}
// The crop's extent along an axis: the cells [lo, hi) that hold `cells` of the target
// about the window's centre, at least 1 and short of the whole grid.
void cropRange(float cells, int* lo, int* hi) {
  const float c = fmath::clampf(cells, 1.f, static_cast<float>(kN - 2));
  *lo = fmath::floorToInt(static_cast<float>(kHalf) - 0.5f * c + 0.5f);
  *hi = fmath::floorToInt(static_cast<float>(kHalf) + 0.5f * c + 0.5f);
  if (*hi <= *lo) *hi = *lo + 1;
}
}  // namespace

BackgroundAwareFilter::BackgroundAwareFilter() {
  float hann[kN];
  for (int i = 0; i < kN; ++i) hann[i] = 0.5f * (1.f - fft::cosTurn(i));
  constexpr float g = -0.5f / (kLabelSigmaCells * kLabelSigmaCells);
  for (int y = 0; y < kN; ++y) {
    for (int x = 0; x < kN; ++x) {
      _cosine[y * kN + x] = hann[y] * hann[x];
      const float dy = static_cast<float>(shiftOf(y)), dx = static_cast<float>(shiftOf(x));
      _yRe[y * kN + x] = fmath::fastExp(g * (dx * dx + dy * dy));
      _yIm[y * kN + x] = 0.f;
      _mask[y * kN + x] = 0.f;
    }
  }
  fft::forward2d(_yRe, _yIm);
}

Box BackgroundAwareFilter::window(const Box& target) {
  const float side = kPadding * fmath::sqrtf(target.w * target.h);
  return Box{target.x + 0.5f * (target.w - side), target.y + 0.5f * (target.h - side), side, side};
}

bool BackgroundAwareFilter::transformed(const RgbView& rgb, const Box& target) {
  if (target.empty() || !_features.extract(rgb, window(target), _x)) return false;
  for (int l = 0; l < K; ++l)
    for (int i = 0; i < kFftSize; ++i) _x[l][i] *= _cosine[i];
  for (int l = 0; l < K; l += 2)
    fft::forwardRealPair(_x[l], _x[l + 1], _zRe[l], _zIm[l], _zRe[l + 1], _zIm[l + 1]);
  return true;
}

ForegroundModel::Rect BackgroundAwareFilter::targetSamples() const {
  constexpr int c = ForegroundModel::kCellPx;
  return ForegroundModel::Rect{_boxX0 * c, _boxY0 * c, _boxX1 * c, _boxY1 * c};
}

void BackgroundAwareFilter::updateMask() {
  int kept = 0, total = 0;
  _colour.likelihood(_features.samples(), _likelihood);
  ForegroundModel::cellMeans(_likelihood, _cells);
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const bool in = y >= _boxY0 && y < _boxY1 && x >= _boxX0 && x < _boxX1;
      const bool target = _cells[y * kN + x] >= kMaskLikelihood;
      _mask[y * kN + x] = in && target ? 1.f : 0.f;
      total += in ? 1 : 0;
      kept += in && target ? 1 : 0;
    }
  // Too few cells look like the target (a box of one colour with its surround): the
  // whole box, as a plain BACF.
  if (static_cast<float>(kept) < kMinMaskShare * static_cast<float>(total))
    for (int y = _boxY0; y < _boxY1; ++y)
      for (int x = _boxX0; x < _boxX1; ++x) _mask[y * kN + x] = 1.f;
}

bool BackgroundAwareFilter::reset(const RgbView& rgb, const Box& target) {
  _ready = false;
  if (!transformed(rgb, target)) return false;
  // The target's cells: its sides over the window's, in cells.
  const float side = kPadding * fmath::sqrtf(target.w * target.h);
  cropRange(static_cast<float>(kN) * target.w / side, &_boxX0, &_boxX1);
  cropRange(static_cast<float>(kN) * target.h / side, &_boxY0, &_boxY1);
  _colour.reset(_features.samples(), targetSamples());
  updateMask();
  for (int l = 0; l < K; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      _mRe[l][i] = _zRe[l][i];
      _mIm[l][i] = _zIm[l][i];
    }
  }
  solve();
  _ready = true;
  return true;
}

void BackgroundAwareFilter::learn(const RgbView& rgb, const Box& target, float rate) {
  if (!_ready || !transformed(rgb, target)) return;
  _colour.learn(_features.samples(), targetSamples(), kColourRate);
  updateMask();
  const float keep = 1.f - rate;
  for (int l = 0; l < K; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      _mRe[l][i] = keep * _mRe[l][i] + rate * _zRe[l][i];
      _mIm[l][i] = keep * _mIm[l][i] + rate * _zIm[l][i];
    }
  }
  solve();
}

void BackgroundAwareFilter::solve() {
  for (int i = 0; i < kFftSize; ++i) _sxx[i] = 0.f;
  for (int l = 0; l < K; ++l) {
    for (int i = 0; i < kFftSize; ++i) {
      _sxx[i] += _mRe[l][i] * _mRe[l][i] + _mIm[l][i] * _mIm[l][i];
      _hRe[l][i] = _hIm[l][i] = _uRe[l][i] = _uIm[l][i] = 0.f;
    }
  }
  float mu = kMu0;
  for (int it = 0; it < kIterations; ++it) {
    // g: q_k = x_k conj(y) + mu h_k - l_k; s = x^H q; g_k = (q_k - x_k s / (mu + x^H x)) / mu.
    for (int i = 0; i < kFftSize; ++i) {
      _sRe[i] = _sxx[i] * _yRe[i];  // x^H x conj(y)
      _sIm[i] = -_sxx[i] * _yIm[i];
    }
    for (int l = 0; l < K; ++l) {
      for (int i = 0; i < kFftSize; ++i) {
        const float dr = mu * _hRe[l][i] - _uRe[l][i], di = mu * _hIm[l][i] - _uIm[l][i];
        const float xr = _mRe[l][i], xi = _mIm[l][i];
        _sRe[i] += xr * dr + xi * di;  // conj(x) d
        _sIm[i] += xr * di - xi * dr;
      }
    }
    const float invMu = 1.f / mu;
    for (int i = 0; i < kFftSize; ++i) {
      const float inv = 1.f / (mu + _sxx[i]);
      _sRe[i] *= inv;
      _sIm[i] *= inv;
    }
    for (int l = 0; l < K; ++l) {
      for (int i = 0; i < kFftSize; ++i) {
        const float xr = _mRe[l][i], xi = _mIm[l][i];
        const float qr = xr * _yRe[i] + xi * _yIm[i] + (mu * _hRe[l][i] - _uRe[l][i]);
        const float qi = xi * _yRe[i] - xr * _yIm[i] + (mu * _hIm[l][i] - _uIm[l][i]);
        _gRe[l][i] = invMu * (qr - (xr * _sRe[i] - xi * _sIm[i]));
        _gIm[l][i] = invMu * (qi - (xr * _sIm[i] + xi * _sRe[i]));
      }
    }
    if (it + 1 == kIterations) break;  // the next h and l would not be used
    // h: the crop of (mu g + l) / (mu + lambda) (two real channels a complex transform),
    // then l += mu (g - h).
    const float shrink = 1.f / (mu + kLambda);
    for (int l = 0; l < K; l += 2) {
      float* re = _map;
      float* im = _mapIm;
      for (int i = 0; i < kFftSize; ++i) {  // (A + iB): A's plane real, B's imaginary
        re[i] = (mu * _gRe[l][i] + _uRe[l][i]) - (mu * _gIm[l + 1][i] + _uIm[l + 1][i]);
        im[i] = (mu * _gIm[l][i] + _uIm[l][i]) + (mu * _gRe[l + 1][i] + _uRe[l + 1][i]);
      }
      fft::inverse2d(re, im);
      for (int i = 0; i < kFftSize; ++i) {
        _x[l][i] = shrink * _mask[i] * re[i];
        _x[l + 1][i] = shrink * _mask[i] * im[i];
      }
      fft::forwardRealPair(_x[l], _x[l + 1], _hRe[l], _hIm[l], _hRe[l + 1], _hIm[l + 1]);
    }
    for (int l = 0; l < K; ++l) {
      for (int i = 0; i < kFftSize; ++i) {
        _uRe[l][i] += mu * (_gRe[l][i] - _hRe[l][i]);
        _uIm[l][i] += mu * (_gIm[l][i] - _hIm[l][i]);
      }
    }
    mu = mu * kMuGrowth < kMuMax ? mu * kMuGrowth : kMuMax;
  }
  measureSelfPeak();
}

void BackgroundAwareFilter::measureSelfPeak() {
  // The response at zero shift on the model: (1/T) sum over frequencies of conj(g) x.
  float r = 0.f;
  for (int l = 0; l < K; ++l) {
    float s = 0.f;
    for (int i = 0; i < kFftSize; ++i) s += _gRe[l][i] * _mRe[l][i] + _gIm[l][i] * _mIm[l][i];
    r += s;
  }
  r /= kT;
  _selfPeak = r > 0.f ? r : 1.f;
}

BackgroundAwareFilter::Answer BackgroundAwareFilter::search(const RgbView& rgb, const Box& target) {
  Answer a;
  if (!_ready || !transformed(rgb, target)) return a;
  float* re = _map;
  float* im = _mapIm;
  for (int i = 0; i < kFftSize; ++i) re[i] = im[i] = 0.f;
  for (int l = 0; l < K; ++l) {
    for (int i = 0; i < kFftSize; ++i) {  // conj(g) z
      const float gr = _gRe[l][i], gi = _gIm[l][i], zr = _zRe[l][i], zi = _zIm[l][i];
      re[i] += gr * zr + gi * zi;
      im[i] += gr * zi - gi * zr;
    }
  }
  fft::inverse2d(re, im);
  // The map on its model's scale: 1 on what it learnt.
  const float scale = 1.f / _selfPeak;
  for (int i = 0; i < kFftSize; ++i) re[i] *= scale;
  int best = 0;
  for (int i = 1; i < kFftSize; ++i)
    if (re[i] > re[best]) best = i;
  const int py = best / kN, px = best % kN;
  const float fx = vertex(re[py * kN + ((px + kN - 1) & (kN - 1))], re[best],
                          re[py * kN + ((px + 1) & (kN - 1))]);
  const float fy = vertex(re[((py + kN - 1) & (kN - 1)) * kN + px], re[best],
                          re[((py + 1) & (kN - 1)) * kN + px]);
  const float cell = window(target).w / static_cast<float>(kN);
  const float sx = static_cast<float>(shiftOf(px)) + fx, sy = static_cast<float>(shiftOf(py)) + fy;
  a.box = Box{target.x + sx * cell, target.y + sy * cell, target.w, target.h};
  a.peak = re[best];
  float mean = 0.f;
  for (int i = 0; i < kFftSize; ++i) mean += re[i];
  mean /= kT;
  float var = 0.f;
  for (int i = 0; i < kFftSize; ++i) var += (re[i] - mean) * (re[i] - mean);
  var /= kT;
  a.psr = var > 0.f ? (a.peak - mean) / fmath::sqrtf(var) : 0.f;
  a.valid = true;
  return a;
}

}  // namespace cuetrack
