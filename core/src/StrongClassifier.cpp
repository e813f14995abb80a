#include "cuetrack/core/StrongClassifier.hpp"

namespace cuetrack {

bool StrongClassifier::train(const FeaturePool& pool, const ResponseCache& cache,
                             const TrainingSet& set, int m, float* featureErrors) {
  const int n = set.capacity();
  const int8_t* y = set.labels();
  const int numPos = set.numPositives(), numNeg = set.numNegatives();
  if (numPos == 0 || numNeg == 0 || pool.size() == 0) return false;
  if (m > kMaxWeakClassifiers) m = kMaxWeakClassifiers;
  float w[kMaxTrainingExamples];
  float c[kMaxTrainingExamples];  // running sum of f_m(x_i)
  for (int i = 0; i < n; ++i) {
    c[i] = 0.f;
    if (!set.used(i))
      w[i] = 0.f;
    else
      w[i] = y[i] > 0 ? 0.5f / static_cast<float>(numPos) : 0.5f / static_cast<float>(numNeg);
  }
  _m = 0;
  for (int round = 0; round < m; ++round) {
    int best = -1;
    float bestErr = 0.f;
    for (int f = 0; f < pool.size(); ++f) {
      const float e = WeakClassifier::binnedError(cache.row(f), w, y, n);
      if (round == 0 && featureErrors != nullptr) featureErrors[f] = e;
      if (best < 0 || e < bestErr) {
        best = f;
        bestErr = e;
      }
    }
    const Code* codes = cache.row(best);
    _feature[_m] = pool[best];
    _weak[_m].fit(codes, w, y, n, pool[best].kind);
    float total = 0.f;
    for (int i = 0; i < n; ++i) {
      if (w[i] <= 0.f) continue;
      const float f = _weak[_m].predict(codes[i]);
      c[i] += f;
      w[i] *= fmath::fastExp(-static_cast<float>(y[i]) * f);
      total += w[i];
    }
    ++_m;
    if (!(total > 0.f)) break;
    const float inv = 1.f / total;
    for (int i = 0; i < n; ++i) w[i] *= inv;
  }
  // Training error of sign(c), examples weighted half per class.
  float err = 0.f;
  for (int i = 0; i < n; ++i) {
    if (!set.used(i)) continue;
    const bool wrong = y[i] > 0 ? !(c[i] > 0.f) : !(c[i] < 0.f);
    if (wrong)
      err += y[i] > 0 ? 0.5f / static_cast<float>(numPos) : 0.5f / static_cast<float>(numNeg);
  }
  _trainingError = err;
  return true;
}

}  // namespace cuetrack
