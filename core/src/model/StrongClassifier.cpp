#include "cuetrack/core/model/StrongClassifier.hpp"

#include <cstring>

namespace cuetrack {

void StrongClassifier::findDistinct() {
  _numDistinct = 0;
  for (int m = 0; m < _m; ++m) {
    const Feature& f = _feature[m];
    int u = 0;
    for (; u < _numDistinct; ++u) {
      const Feature& g = _feature[_distinct[u]];
      // Bitwise: equal bits give equal responses on any window.
      if (f.kind == g.kind && std::memcmp(&f.x, &g.x, sizeof f.x) == 0 &&
          std::memcmp(&f.y, &g.y, sizeof f.y) == 0 && std::memcmp(&f.w, &g.w, sizeof f.w) == 0 &&
          std::memcmp(&f.h, &g.h, sizeof f.h) == 0)
        break;
    }
    if (u == _numDistinct) _distinct[_numDistinct++] = m;
    _distinctOf[m] = u;
  }
}

namespace {
// The whole pool ranked under weights w: the feature of least error (returned, its error
// in *bestErrOut), the `candidates` lowest errors in ascending order into cand and candErr
// (*numCand of them; ties keep pool order), and every feature's error into
// featureErrors (when not null).
int rankPool(const FeaturePool& pool, const ResponseCache& cache, const float* w, int split, int n,
             int candidates, float* featureErrors, int* cand, float* candErr, int* numCand,
             float* bestErrOut) {
  int best = -1;
  float bestErr = 0.f;
  int nc = 0;
  float e4[4];
  for (int f = 0; f < pool.size(); ++f) {
    if (f % 4 == 0 && f + 4 <= pool.size()) {
      const Code* rows[4] = {cache.row(f), cache.row(f + 1), cache.row(f + 2), cache.row(f + 3)};
      WeakClassifier::binnedErrorSplit4(rows, w, split, n, e4);
    }
    const float e = f - f % 4 + 4 <= pool.size()
                        ? e4[f % 4]
                        : WeakClassifier::binnedErrorSplit(cache.row(f), w, split, n);
    if (featureErrors != nullptr) featureErrors[f] = e;
    if (best < 0 || e < bestErr) {
      best = f;
      bestErr = e;
    }
    // Keep the `candidates` lowest errors (insertion; ties keep pool order).
    if (nc < candidates || e < candErr[nc - 1]) {
      int j = nc < candidates ? nc++ : nc - 1;
      while (j > 0 && candErr[j - 1] > e) {
        cand[j] = cand[j - 1];
        candErr[j] = candErr[j - 1];
        --j;
      }
      cand[j] = f;
      candErr[j] = e;
    }
  }
  *numCand = nc;
  *bestErrOut = bestErr;
  return best;
}
}  // namespace

bool StrongClassifier::train(const FeaturePool& pool, const ResponseCache& cache,
                             const TrainingSet& set, int m, float* featureErrors, int candidates,
                             float anchorWeight, int refreshRounds) {
  const int n = set.capacity();
  const int8_t* y = set.labels();
  const int numPos = set.numPositives(), numNeg = set.numNegatives();
  if (numPos == 0 || numNeg == 0 || pool.size() == 0) return false;
  if (m > kMaxWeakClassifiers) m = kMaxWeakClassifiers;
  float w[kMaxTrainingExamples];
  float c[kMaxTrainingExamples];  // running sum of f_m(x_i)
  float posMass = 0.f;
  for (int i = 0; i < n; ++i)
    if (set.used(i) && y[i] > 0) posMass += set.isAnchor(i) ? anchorWeight : 1.f;
  for (int i = 0; i < n; ++i) {
    c[i] = 0.f;
    if (!set.used(i))
      w[i] = 0.f;
    else if (y[i] > 0)
      w[i] = 0.5f * (set.isAnchor(i) ? anchorWeight : 1.f) / posMass;
    else
      w[i] = 0.5f / static_cast<float>(numNeg);
  }
  const int split = set.positiveSlots();  // label layout: positives first
  if (candidates < 1) candidates = 1;
  if (candidates > kMaxPoolFeatures) candidates = kMaxPoolFeatures;
  int cand[kMaxPoolFeatures];  // later rounds' candidates, ascending error at the last ranking
  float candErr[kMaxPoolFeatures];
  int numCand = 0;
  _m = 0;
  for (int round = 0; round < m; ++round) {
    int best = -1;
    float bestErr = 0.f;
    if (round == 0 || (refreshRounds > 0 && round % refreshRounds == 0)) {
      // Rank the whole pool under the current weights.
      best = rankPool(pool, cache, w, split, n, candidates, round == 0 ? featureErrors : nullptr,
                      cand, candErr, &numCand, &bestErr);
    } else {
      float e4[4];
      for (int k = 0; k < numCand; ++k) {
        const int f = cand[k];
        if (k % 4 == 0 && k + 4 <= numCand) {
          const Code* rows[4] = {cache.row(f), cache.row(cand[k + 1]), cache.row(cand[k + 2]),
                                 cache.row(cand[k + 3])};
          WeakClassifier::binnedErrorSplit4(rows, w, split, n, e4);
        }
        const float e = k - k % 4 + 4 <= numCand
                            ? e4[k % 4]
                            : WeakClassifier::binnedErrorSplit(cache.row(f), w, split, n);
        if (best < 0 || e < bestErr) {
          best = f;
          bestErr = e;
        }
      }
    }
    const Code* codes = cache.row(best);
    _feature[_m] = pool[best];
    _weak[_m].fit(codes, w, y, n, pool[best].kind, &_shares);
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
  findDistinct();
  return true;
}

}  // namespace cuetrack
