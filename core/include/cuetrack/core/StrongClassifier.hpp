// GentleBoost (Friedman, Hastie & Tibshirani 2000) over the feature pool:
// c(x) = (1/M) sum_m f_m(x) in [-1, 1]. Each round picks the pool feature whose
// binned weak classifier has the least weighted squared error, fits its lognormal
// weak classifier to the current weights, and reweights w_i *= exp(-y_i f_m(x_i)).
// Positives and negatives start with half the total weight each.
#pragma once

#include <cstdint>

#include "cuetrack/core/Config.hpp"
#include "cuetrack/core/FeaturePool.hpp"
#include "cuetrack/core/TrainingSet.hpp"
#include "cuetrack/core/WeakClassifier.hpp"

namespace cuetrack {

class StrongClassifier {
 public:
  // Trains M rounds. featureErrors (pool size) receives each feature's first-round
  // error (the pool update's ranking). False when there are no positives or negatives.
  bool train(const FeaturePool& pool, const ResponseCache& cache, const TrainingSet& set, int m,
             float* featureErrors);
  // c(x) for window `win` (frame px) on the frame tables.
  template <typename U, typename S>
  float evaluate(const ChannelTables<U, S>& t, const Box& win) const {
    float sum = 0.f;
    for (int i = 0; i < _m; ++i) sum += _weak[i].predict(cuetrack::evaluate(_feature[i], win, t));
    return _m > 0 ? sum / static_cast<float>(_m) : 0.f;
  }
  int size() const { return _m; }
  const Feature& feature(int i) const { return _feature[i]; }
  const WeakClassifier& weak(int i) const { return _weak[i]; }
  // Training-set error of the last training: weighted fraction misclassified by sign(c).
  float trainingError() const { return _trainingError; }

 private:
  Feature _feature[kMaxWeakClassifiers];
  WeakClassifier _weak[kMaxWeakClassifiers];
  int _m = 0;
  float _trainingError = 0.f;
};

}  // namespace cuetrack
