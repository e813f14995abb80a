#include "cuetrack/core/guards/Occlusion.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack::occlusion {

float nearerFraction(const DepthView& depth, const Box& box, float nearMm) {
  if (depth.empty() || box.empty() || !(nearMm > 0.f)) return 0.f;
  const PixelRect r = clipBox(box, depth.width, depth.height);
  if (r.width() < 1 || r.height() < 1) return 0.f;
  const int nx = r.width() < kGrid ? r.width() : kGrid;
  const int ny = r.height() < kGrid ? r.height() : kGrid;
  const uint16_t nearI = nearMm > 65535.f ? uint16_t{65535} : static_cast<uint16_t>(nearMm);
  int valid = 0, nearer = 0;
  for (int j = 0; j < ny; ++j) {
    // Sample centres: (j + 1/2) / ny of the way down (and likewise across).
    const uint16_t* row = depth.row(r.y0 + (2 * j + 1) * r.height() / (2 * ny));
    for (int i = 0; i < nx; ++i) {
      const uint16_t d = row[r.x0 + (2 * i + 1) * r.width() / (2 * nx)];
      if (d == 0) continue;
      ++valid;
      if (d < nearI) ++nearer;
    }
  }
  return valid > 0 ? static_cast<float>(nearer) / static_cast<float>(valid) : 0.f;
}

float occluderBelowMm(float frontMm, float diameterMm) {
  const float noiseMm = tuning::occlusion::kGapRatio * frontMm;
  return frontMm - 0.5f * diameterMm -
         (noiseMm > tuning::occlusion::kMinGapMm ? noiseMm : tuning::occlusion::kMinGapMm);
}

}  // namespace cuetrack::occlusion

namespace cuetrack {

void LearntMotion::add(uint64_t timeUs, const float p[3]) {
  // Time going back (a new recording, a seek): start again.
  if (_count > 0 && timeUs <= _timeUs[(_next + kSamples - 1) % kSamples]) clear();
  _timeUs[_next] = timeUs;
  for (int a = 0; a < 3; ++a) _p[_next][a] = p[a];
  _next = (_next + 1) % kSamples;
  if (_count < kSamples) ++_count;
}

bool LearntMotion::velocity(float out[3]) const {
  out[0] = out[1] = out[2] = 0.f;
  if (_count < kMinSamples) return false;
  const int newest = (_next + kSamples - 1) % kSamples;
  // Times relative to the newest sample [s] (small numbers: float keeps them exact enough).
  float st = 0.f, stt = 0.f, sp[3] = {0.f, 0.f, 0.f}, stp[3] = {0.f, 0.f, 0.f};
  int n = 0;
  float oldestS = 0.f;
  for (int k = 0; k < _count; ++k) {
    const int i = (newest + kSamples - k) % kSamples;
    const float t = -static_cast<float>(_timeUs[newest] - _timeUs[i]) * 1e-6f;
    if (-t > kMaxSpanS) break;
    st += t;
    stt += t * t;
    for (int a = 0; a < 3; ++a) {
      sp[a] += _p[i][a];
      stp[a] += t * _p[i][a];
    }
    oldestS = t;
    ++n;
  }
  if (n < kMinSamples || -oldestS < kMinSpanS) return false;
  const float fn = static_cast<float>(n);
  const float den = fn * stt - st * st;
  if (!(den > 0.f)) return false;
  for (int a = 0; a < 3; ++a) out[a] = (fn * stp[a] - st * sp[a]) / den;
  return true;
}

}  // namespace cuetrack
