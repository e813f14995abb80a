#include "cuetrack/core/model/FeaturePool.hpp"

namespace cuetrack {

namespace {
constexpr float kMinDynamicSize = 0.15f;  // of the window side
constexpr float kMaxDynamicSize = 0.6f;
constexpr float kColourSigma = 0.15f;
}  // namespace

bool FeaturePool::push(const Feature& f) {
  if (_n >= kMaxPoolFeatures) return false;
  _f[_n++] = f;
  return true;
}

void FeaturePool::addGrid(FeatureKind kind, bool dense) {
  Feature whole;
  whole.kind = kind;
  whole.isStatic = true;
  push(whole);
  const int divisions[3] = {2, 3, 4};
  for (int d : divisions) {
    const float s = 1.f / static_cast<float>(d);
    const int steps = dense ? 2 * d - 1 : d;  // dense: half-size steps
    const float step = dense ? 0.5f * s : s;
    for (int j = 0; j < steps; ++j)
      for (int i = 0; i < steps; ++i) {
        Feature f;
        f.kind = kind;
        f.isStatic = true;
        f.x = static_cast<float>(i) * step;
        f.y = static_cast<float>(j) * step;
        f.w = s;
        f.h = s;
        push(f);
      }
  }
}

Feature FeaturePool::sample(FeatureKind kind, Rng& rng) {
  Feature f;
  f.kind = kind;
  f.isStatic = false;
  f.w = rng.uniform(kMinDynamicSize, kMaxDynamicSize);
  f.h = rng.uniform(kMinDynamicSize, kMaxDynamicSize);
  if (kind == FeatureKind::Colour) {
    float cx, cy;
    do {  // truncated Gaussian by rejection (acceptance ~99.8%)
      cx = 0.5f + kColourSigma * rng.gaussian();
      cy = 0.5f + kColourSigma * rng.gaussian();
    } while (cx < 0.f || cx > 1.f || cy < 0.f || cy > 1.f);
    f.x = fmath::clampf(cx - 0.5f * f.w, 0.f, 1.f - f.w);
    f.y = fmath::clampf(cy - 0.5f * f.h, 0.f, 1.f - f.h);
  } else {
    f.x = rng.uniform(0.f, 1.f - f.w);
    f.y = rng.uniform(0.f, 1.f - f.h);
  }
  return f;
}

bool FeaturePool::build(bool useGray, bool useDepth, bool useColour, FeatureSampling sampling,
                        Rng& rng) {
  _n = 0;
  _enabled[static_cast<int>(FeatureKind::Gray)] = useGray;
  _enabled[static_cast<int>(FeatureKind::Depth)] = useDepth;
  _enabled[static_cast<int>(FeatureKind::Colour)] = useColour;
  const bool dense = sampling == FeatureSampling::Dense;
  for (int k = 0; k < kNumFeatureKinds; ++k) {
    if (!_enabled[k]) continue;
    addGrid(static_cast<FeatureKind>(k), dense);
    if (!dense)
      for (int i = 0; i < kDynamicFeaturesPerKind; ++i)
        if (!push(sample(static_cast<FeatureKind>(k), rng))) return false;
  }
  return _n <= kMaxPoolFeatures;
}

int FeaturePool::count(FeatureKind k, bool dynamicOnly) const {
  int c = 0;
  for (int i = 0; i < _n; ++i)
    if (_f[i].kind == k && (!dynamicOnly || !_f[i].isStatic)) ++c;
  return c;
}

int FeaturePool::update(const float* errors, Rng& rng) {
  float sum[kNumFeatureKinds] = {}, meanErr[kNumFeatureKinds] = {};
  int n[kNumFeatureKinds] = {}, nDyn[kNumFeatureKinds] = {};
  for (int i = 0; i < _n; ++i) {
    const int k = static_cast<int>(_f[i].kind);
    sum[k] += errors[i];
    ++n[k];
    if (!_f[i].isStatic) ++nDyn[k];
  }
  float pRemove[kNumFeatureKinds] = {}, pAdd[kNumFeatureKinds] = {};
  float totRemove = 0.f, totAdd = 0.f;
  for (int k = 0; k < kNumFeatureKinds; ++k) {
    if (!_enabled[k] || n[k] == 0) continue;
    meanErr[k] = sum[k] / static_cast<float>(n[k]);
    if (nDyn[k] > 0) pRemove[k] = meanErr[k] + 1e-6f;
    pAdd[k] = (1.f - meanErr[k]) + 1e-6f;
    if (pAdd[k] < 1e-6f) pAdd[k] = 1e-6f;
    totRemove += pRemove[k];
    totAdd += pAdd[k];
  }
  if (totRemove <= 0.f || totAdd <= 0.f) return -1;
  auto pick = [&rng](const float* p, float total) {
    float u = rng.uniform() * total;
    int last = 0;
    for (int k = 0; k < kNumFeatureKinds; ++k) {
      if (p[k] <= 0.f) continue;
      last = k;
      if (u < p[k]) return k;
      u -= p[k];
    }
    return last;
  };
  const int kr = pick(pRemove, totRemove);
  const int ka = pick(pAdd, totAdd);
  int worst = -1;
  for (int i = 0; i < _n; ++i) {
    if (_f[i].isStatic || static_cast<int>(_f[i].kind) != kr) continue;
    if (worst < 0 || errors[i] > errors[worst]) worst = i;
  }
  if (worst < 0) return -1;
  _f[worst] = sample(static_cast<FeatureKind>(ka), rng);
  return worst;
}

}  // namespace cuetrack
