#include "cuetrack/core/filter/ParticleFilter.hpp"

namespace cuetrack {

void MotionModel2d::predict(Particle& q, Rng& rng, float spread, int framesElapsed) const {
  const float side = fmath::sqrtf(q.size[0] * q.size[1]);
  const float frames = static_cast<float>(framesElapsed);
  for (int a = 0; a < 2; ++a) {
    q.v[a] = velocityDecay * q.v[a] + spread * velocityNoise * side * rng.gaussianFast();
    q.p[a] += frames * q.v[a] + spread * positionNoise * side * rng.gaussianFast();
  }
  const float ls = scaleNoise * rng.gaussianFast();
  const float la = aspectNoise * rng.gaussianFast();
  q.size[0] *= fmath::fastExp(ls + la);
  q.size[1] *= fmath::fastExp(ls - la);
}

void MotionModel2d::jump(Particle& q, Rng& rng, float scale) const {
  const float std = scale * positionNoise * fmath::sqrtf(q.size[0] * q.size[1]);
  for (int a = 0; a < 2; ++a) {
    const float d = std * rng.gaussianFast();
    q.p[a] += d;
    q.v[a] += d;
  }
}

int FramePeriod::framesElapsed(uint64_t dtUs) {
  int frames = 1;
  if (_count > 0) {
    // Median of the history (insertion sort of at most kHistory values).
    uint64_t sorted[kHistory];
    for (int i = 0; i < _count; ++i) {
      uint64_t x = _dtUs[i];
      int j = i;
      for (; j > 0 && sorted[j - 1] > x; --j) sorted[j] = sorted[j - 1];
      sorted[j] = x;
    }
    const uint64_t periodUs = sorted[_count / 2];
    if (periodUs > 0) {
      const uint64_t n = (dtUs + periodUs / 2) / periodUs;
      frames = n < 1 ? 1 : n > static_cast<uint64_t>(kMaxGap) ? kMaxGap : static_cast<int>(n);
    }
  }
  _dtUs[_next] = dtUs;
  _next = (_next + 1) % kHistory;
  if (_count < kHistory) ++_count;
  return frames;
}

void MotionModel3d::predict(Particle& q, Rng& rng, float dtS, float spread) const {
  const float velStd = fmath::sqrtf(velocityNoiseMm2PerS2 * dtS);
  const float posStd = spread * positionNoise * q.size[0] * fmath::sqrtf(dtS * 30.f);
  for (int a = 0; a < 3; ++a) {
    q.p[a] += q.v[a] * dtS + posStd * rng.gaussianFast();
    q.v[a] += velStd * rng.gaussianFast();
  }
  if (sizeNoise > 0.f) {
    q.size[0] *= fmath::fastExp(sizeNoise * rng.gaussianFast());
    q.size[1] *= fmath::fastExp(sizeNoise * rng.gaussianFast());
  }
}

void MotionModel3d::jump(Particle& q, Rng& rng, float dtS, float scale) const {
  const float std = scale * positionNoise * q.size[0] * fmath::sqrtf(dtS * 30.f);
  const float invDt = dtS > 0.f ? 1.f / dtS : 0.f;
  for (int a = 0; a < 2; ++a) {
    const float d = std * rng.gaussianFast();
    q.p[a] += d;
    q.v[a] += d * invDt;
  }
}

Box projectCylinder(const Particle& q, const CameraIntrinsics& k) {
  const float z = q.p.z();
  if (!(z > 50.f)) return Box{};
  const float inv = 1.f / z;
  const Eigen::Vector2f c = project(k, q.p);
  const float w = k.fx * q.size[0] * inv, h = k.fy * q.size[1] * inv;
  return Box{c.x() - 0.5f * w, c.y() - 0.5f * h, w, h};
}

Particle cylinderFromBox(const Box& b, float surfaceMm, const CameraIntrinsics& k) {
  Particle q;
  const float D = b.w * surfaceMm / (k.fx - 0.5f * b.w);
  const float zc = surfaceMm + 0.5f * D;
  const float H = b.h * zc / k.fy;
  q.p = backProject(k, b.x + 0.5f * b.w, b.y + 0.5f * b.h, zc);
  q.size = Eigen::Vector2f(D, H);
  return q;
}

bool keepInView(Particle& q, const CameraIntrinsics& k, int imageW, int imageH) {
  bool moved = false;
  if (!(q.p[2] >= kMinCylinderDepthMm) || q.p[2] > static_cast<float>(kMaxDepthMm)) {
    q.p[2] = q.p[2] > static_cast<float>(kMaxDepthMm) ? static_cast<float>(kMaxDepthMm)
                                                      : kMinCylinderDepthMm;
    q.v[2] = 0.f;
    moved = true;
  }
  const float z = q.p[2];
  const float lim[2] = {static_cast<float>(imageW), static_cast<float>(imageH)};
  const float f[2] = {k.fx, k.fy}, c[2] = {k.cx, k.cy};
  for (int a = 0; a < 2; ++a) {
    const float u = f[a] * q.p[a] / z + c[a];
    if (u >= 0.f && u <= lim[a]) continue;
    const float edge = u < 0.f ? 0.f : lim[a];
    q.p[a] = (edge - c[a]) * z / f[a];
    q.v[a] = 0.f;
    moved = true;
  }
  return moved;
}

bool correctDepth(Particle& q, const IntegralChannels& ch, const CameraIntrinsics& k, float dtS,
                  int imageW, int imageH) {
  const Box b = projectCylinder(q, k);
  if (b.empty()) return false;
  float iw = 0.1f * b.w, ih = 0.1f * b.h;
  if (iw < 2.f) iw = 2.f;
  if (ih < 2.f) ih = 2.f;
  const Box inner{b.x + 0.5f * (b.w - iw), b.y + 0.5f * (b.h - ih), iw, ih};
  const float d = ch.meanDepthMm(clipBox(inner, imageW, imageH));
  if (!(d > 0.f)) return false;
  const float zNew = d + 0.5f * q.size[0];
  const float s = zNew / q.p[2];
  // Along the viewing ray: the centre scaled about the camera.
  const Eigen::Vector3f moved = q.p * s;
  // A frame this soon after the last (a repeated or near-duplicate frame) says nothing
  // about velocity: move / dt would fling the particle (200 us: 12 m/s on average).
  const float invDt = dtS >= kMinVelocityDtS ? 1.f / dtS : 0.f;
  q.v += (moved - q.p) * invDt;
  q.p = moved;
  return true;
}

void ParticleFilter::fill(const Particle& q) {
  for (int i = 0; i < _n; ++i) {
    _p[i] = q;
    _w[i] = 1.f;
  }
}

void ParticleFilter::weigh(Span<const float> scores, Span<const float> cueScores) {
  const int n = _n;
  float cMax = -2.f;
  for (int i = 0; i < n; ++i)
    if (scores[i] > cMax) cMax = scores[i];
  float* w = _w;
  if (!cueScores.empty()) {
    float rMax = -2.f;
    for (int i = 0; i < n; ++i)
      if (cueScores[i] > rMax) rMax = cueScores[i];
    for (int i = 0; i < n; ++i)
      w[i] = fmath::fastExp(tuning::kWeightGain * (scores[i] - cMax) +
                            tuning::correlation::kResponseGain * (cueScores[i] - rMax));
  } else {
    for (int i = 0; i < n; ++i) w[i] = fmath::fastExp(tuning::kWeightGain * (scores[i] - cMax));
  }
}

float ParticleFilter::concentration(Span<const Box> boxes, const Box& estimate) const {
  float concentration = 0.f, wsum = 0.f;
  for (int i = 0; i < _n; ++i) {
    concentration += _w[i] * overlap(boxes[i], estimate);
    wsum += _w[i];
  }
  return wsum > 0.f ? concentration / wsum : 0.f;
}

void ParticleFilter::resample(Rng& rng) {
  float total = 0.f;
  for (int i = 0; i < _n; ++i) total += _w[i];
  if (!(total > 0.f)) {
    for (int i = 0; i < _n; ++i) _w[i] = 1.f;
    return;
  }
  const float step = total / static_cast<float>(_n);
  float u = rng.uniform() * step;
  float cum = _w[0];
  int j = 0;
  for (int i = 0; i < _n; ++i) {
    while (u > cum && j < _n - 1) cum += _w[++j];
    _scratch[i] = _p[j];
    u += step;
  }
  for (int i = 0; i < _n; ++i) {
    _p[i] = _scratch[i];
    _w[i] = 1.f;
  }
}

int ParticleFilter::argmaxWeight() const {
  int best = 0;
  for (int i = 1; i < _n; ++i)
    if (_w[i] > _w[best]) best = i;
  return best;
}

Particle ParticleFilter::weightedMean(const uint8_t* include) const {
  Particle m;
  float total = 0.f;
  for (int i = 0; i < _n; ++i)
    if (include == nullptr || include[i] != 0) total += _w[i];
  if (!(total > 0.f)) return _p[0];
  const float inv = 1.f / total;
  for (int i = 0; i < _n; ++i) {
    if (include != nullptr && include[i] == 0) continue;
    const float w = _w[i] * inv;
    m.p += w * _p[i].p;
    m.v += w * _p[i].v;
    m.size += w * _p[i].size;
  }
  return m;
}

}  // namespace cuetrack
