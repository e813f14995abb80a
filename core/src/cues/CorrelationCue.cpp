#include "cuetrack/core/cues/CorrelationCue.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/kernels/Integral.hpp"

namespace cuetrack {

namespace {
constexpr float kMinSpread = 1e-3f;  // a flat template or patch: no correlation to measure

int roundPx(float v) {
  return static_cast<int>(v >= 0.f ? v + 0.5f : v - 0.5f);
}

// The mean gray of frame rectangle [x0, x1) x [y0, y1) (at least one pixel wide and high),
// false when it is not all on the tables.
bool cellMean(const FrameTables& t, int x0, int y0, int x1, int y1, float* mean) {
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  x0 -= t.originX;
  x1 -= t.originX;
  y0 -= t.originY;
  y1 -= t.originY;
  if (x0 < 0 || y0 < 0 || x1 > t.width || y1 > t.height) return false;
  const uint32_t s = integral::rectSum(t.gray, t.stride, x0, y0, x1, y1);
  *mean = static_cast<float>(s) / static_cast<float>((x1 - x0) * (y1 - y0));
  return true;
}
}  // namespace

bool CorrelationCue::cells(const FrameTables& t, const Box& win, float* out) {
  if (win.empty() || t.gray == nullptr) return false;
  const float cw = win.w / static_cast<float>(kCells);
  const float ch = win.h / static_cast<float>(kCells);
  for (int r = 0; r < kCells; ++r) {
    const int y0 = roundPx(win.y + static_cast<float>(r) * ch);
    const int y1 = roundPx(win.y + static_cast<float>(r + 1) * ch);
    for (int c = 0; c < kCells; ++c) {
      const int x0 = roundPx(win.x + static_cast<float>(c) * cw);
      const int x1 = roundPx(win.x + static_cast<float>(c + 1) * cw);
      if (!cellMean(t, x0, y0, x1, y1, &out[r * kCells + c])) return false;
    }
  }
  return true;
}

bool CorrelationCue::normalise() {
  // The NCC is then the unit template's dot product with a patch over the patch's spread.
  constexpr int n = kCells * kCells;
  float mean = 0.f;
  for (float v : _template) mean += v;
  mean /= static_cast<float>(n);
  float norm = 0.f;
  for (int i = 0; i < n; ++i) {
    _unit[i] = _template[i] - mean;
    norm += _unit[i] * _unit[i];
  }
  _flat = !(norm > kMinSpread);
  if (_flat) return false;
  norm = fmath::sqrtf(norm);
  for (float& v : _unit) v /= norm;
  return true;
}

bool CorrelationCue::reset(const FrameTables& t, const Box& win) {
  _ready = false;
  _searched = false;
  _peak = kNoResponse;
  _ready = cells(t, win, _template) && normalise();
  return _ready;
}

void CorrelationCue::learn(const FrameTables& t, const Box& win, float rate) {
  float now[kCells * kCells];
  if (!_ready || !cells(t, win, now)) return;
  for (int i = 0; i < kCells * kCells; ++i) _template[i] += rate * (now[i] - _template[i]);
  normalise();
}

bool CorrelationCue::search(const FrameTables& t, const Box& around) {
  _searched = false;
  _peak = kNoResponse;
  if (!_ready || _flat || around.empty()) return false;
  constexpr int n = kCells * kCells;
  const float* tz = _unit;

  _cellW = around.w / static_cast<float>(kCells);
  _cellH = around.h / static_cast<float>(kCells);
  _originX = around.x - static_cast<float>(kReach) * _cellW;
  _originY = around.y - static_cast<float>(kReach) * _cellH;
  float* const grid = _grid;  // short names for the index arithmetic below
  double* const sum = _sum;
  double* const sumSq = _sumSq;
  int* const off = _off;
  constexpr int s = kStride;
  for (int i = 0; i < s; ++i) {
    sum[i] = sumSq[i] = 0.0;
    off[i] = 0;
    sum[i * s] = sumSq[i * s] = 0.0;
    off[i * s] = 0;
  }
  for (int r = 0; r < kGrid; ++r) {
    const int y0 = roundPx(_originY + static_cast<float>(r) * _cellH);
    const int y1 = roundPx(_originY + static_cast<float>(r + 1) * _cellH);
    double rowSum = 0.0, rowSq = 0.0;
    int rowOff = 0;
    for (int c = 0; c < kGrid; ++c) {
      const int x0 = roundPx(_originX + static_cast<float>(c) * _cellW);
      const int x1 = roundPx(_originX + static_cast<float>(c + 1) * _cellW);
      float v = 0.f;
      if (!cellMean(t, x0, y0, x1, y1, &v)) ++rowOff;
      grid[r * kGrid + c] = v;
      rowSum += static_cast<double>(v);
      rowSq += static_cast<double>(v) * static_cast<double>(v);
      const int k = (r + 1) * s + c + 1;
      sum[k] = sum[k - s] + rowSum;
      sumSq[k] = sumSq[k - s] + rowSq;
      off[k] = off[k - s] + rowOff;
    }
  }
  int best = -1;
  for (int oy = 0; oy < kOffsets; ++oy) {
    for (int ox = 0; ox < kOffsets; ++ox) {
      float& out = _response[oy * kOffsets + ox];
      out = kNoResponse;
      const int a = oy * s + ox, b = oy * s + ox + kCells;
      const int c = (oy + kCells) * s + ox, d = (oy + kCells) * s + ox + kCells;
      if (off[d] - off[b] - off[c] + off[a] != 0) continue;  // partly off the tables
      const double ps = sum[d] - sum[b] - sum[c] + sum[a];
      const double pq = sumSq[d] - sumSq[b] - sumSq[c] + sumSq[a];
      const double var = pq - ps * ps / static_cast<double>(n);
      if (!(var > static_cast<double>(kMinSpread))) {
        out = 0.f;  // a flat patch: uncorrelated
        continue;
      }
      float dot = 0.f;
      for (int r = 0; r < kCells; ++r) {
        const float* row = grid + (oy + r) * kGrid + ox;
        const float* tr = tz + r * kCells;
        for (int k = 0; k < kCells; ++k) dot += tr[k] * row[k];
      }
      out = dot / static_cast<float>(__builtin_sqrt(var));
      if (best < 0 || out > _response[best]) best = oy * kOffsets + ox;
    }
  }
  _searched = true;
  if (best < 0) return true;
  _peak = _response[best];
  _peakBox = Box{_originX + static_cast<float>(best % kOffsets) * _cellW,
                 _originY + static_cast<float>(best / kOffsets) * _cellH, around.w, around.h};
  return true;
}

float CorrelationCue::at(float u, float v) const {
  if (!_searched) return kNoResponse;
  // Offset (ox, oy) puts a window's centre at origin + (o + kCells / 2) cells.
  const float fx = (u - _originX) / _cellW - 0.5f * static_cast<float>(kCells);
  const float fy = (v - _originY) / _cellH - 0.5f * static_cast<float>(kCells);
  // Off the map (or NaN) before the conversion: a float beyond int's range converts
  // differently on x86 and ARM.
  constexpr float lim = static_cast<float>(kOffsets);
  if (!(fx > -1.f && fx < lim && fy > -1.f && fy < lim)) return kNoResponse;
  const int ox = roundPx(fx), oy = roundPx(fy);
  if (ox < 0 || oy < 0 || ox >= kOffsets || oy >= kOffsets) return kNoResponse;
  return _response[oy * kOffsets + ox];
}

}  // namespace cuetrack
