// GentleBoost (Friedman, Hastie & Tibshirani 2000) over the feature pool:
// c(x) = (1/M) sum_m f_m(x) in [-1, 1]. Each round picks the pool feature whose
// binned weak classifier has the least weighted squared error, fits its lognormal
// weak classifier to the current weights, and reweights w_i *= exp(-y_i f_m(x_i)).
// Positives and negatives start with half the total weight each. For speed, round 0
// ranks the whole pool and later rounds search only its `candidates` best features;
// every `refreshRounds` rounds the whole pool is ranked again under the current
// weights (the features that separate the examples still wrong are rarely among the
// round-0 best: without it BoBoT 1.1 loses 1.3 points, docs/benchmarks.md).
#pragma once

#include <cstdint>
#include <type_traits>

#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/model/CellKernels.hpp"
#include "cuetrack/core/model/FeaturePool.hpp"
#include "cuetrack/core/model/TrainingSet.hpp"
#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack {

class StrongClassifier {
 public:
  // Trains M rounds. featureErrors (pool size) receives each feature's first-round
  // error (the pool update's ranking). False when there are no positives or negatives.
  StrongClassifier() { _shares.build(); }
  bool train(const FeaturePool& pool, const ResponseCache& cache, const TrainingSet& set, int m,
             float* featureErrors, int candidates = kMaxPoolFeatures, float anchorWeight = 1.f,
             int refreshRounds = 0);  // 0: never
  // c(x) for window `win` (frame px) on the frame tables.
  template <typename U, typename S>
  float evaluate(const ChannelTables<U, S>& t, const Box& win) const {
    float sum = 0.f;
    for (int i = 0; i < _m; ++i) sum += _weak[i].predict(cuetrack::evaluate(_feature[i], win, t));
    return _m > 0 ? sum / static_cast<float>(_m) : 0.f;
  }
  // c(x) for every window of `windows` at once into out (as many); windows with
  // valid[i] == 0 get -1. Boosting often picks
  // a feature more than once, so each distinct feature is evaluated once per window (its
  // table cell kept), then the weak classifiers' values are summed in round order, as
  // evaluate() does, and scaled by 1/M (within an ulp of evaluate()'s sum / M; the two
  // are only ever compared with margins far above that). `order` (optional) is the visiting order
  // of the windows: nearby windows in turn keep the table rows they read in cache.
  template <typename U, typename S>
  void evaluateMany(const ChannelTables<U, S>& t, Span<const Box> windows,
                    Span<const uint8_t> validity, Span<float> scores,
                    const uint16_t* order = nullptr) const {
    const Box* wins = windows.data();
    const uint8_t* valid = validity.data();
    float* out = scores.data();
    const int n = windows.size();
    const ChannelTables<U, S> tl = t;  // a local copy: the compiler keeps it in registers
    for (int u = 0; u < _numDistinct; ++u) {
      const Feature f = _feature[_distinct[u]];
      uint16_t* cells = _cells[u];
      switch (f.kind) {
        case FeatureKind::Gray:
          codeCells<FeatureKind::Gray>(f, tl, wins, valid, n, cells, order);
          break;
        case FeatureKind::Depth:
          codeCells<FeatureKind::Depth>(f, tl, wins, valid, n, cells, order);
          break;
        case FeatureKind::Colour:
          codeCells<FeatureKind::Colour>(f, tl, wins, valid, n, cells, order);
          break;
      }
    }
    // Four windows at a time, each summing its weak classifiers in round order (the
    // same additions as one pass per round, without storing partial sums).
    const float inv = _m > 0 ? 1.f / static_cast<float>(_m) : 0.f;
    int i = 0;
    for (; i + 4 <= n; i += 4) {
      float s0 = 0.f, s1 = 0.f, s2 = 0.f, s3 = 0.f;
      for (int m = 0; m < _m; ++m) {
        const WeakClassifier& w = _weak[m];
        const uint16_t* cells = _cells[_distinctOf[m]] + i;
        s0 += w.predictCell(cells[0]);
        s1 += w.predictCell(cells[1]);
        s2 += w.predictCell(cells[2]);
        s3 += w.predictCell(cells[3]);
      }
      out[i] = valid[i] ? s0 * inv : -1.f;
      out[i + 1] = valid[i + 1] ? s1 * inv : -1.f;
      out[i + 2] = valid[i + 2] ? s2 * inv : -1.f;
      out[i + 3] = valid[i + 3] ? s3 * inv : -1.f;
    }
    for (; i < n; ++i) {
      float s = 0.f;
      for (int m = 0; m < _m; ++m) s += _weak[m].predictCell(_cells[_distinctOf[m]][i]);
      out[i] = valid[i] ? s * inv : -1.f;
    }
  }
  int size() const { return _m; }
  const Feature& feature(int i) const { return _feature[i]; }
  const WeakClassifier& weak(int i) const { return _weak[i]; }
  // Training-set error of the last training: weighted fraction misclassified by sign(c).
  float trainingError() const { return _trainingError; }

 private:
  // Table cell of feature f (kind K) for every window; kLutCells for invalid windows.
  template <FeatureKind K, typename U, typename S>
  static void codeCells(const Feature& f, const ChannelTables<U, S>& t, const Box* wins,
                        const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
    int k = 0;
    if constexpr (K != FeatureKind::Depth && std::is_same_v<U, uint32_t> &&
                  std::is_same_v<S, int32_t>)
      k = cellk::codeFrame(K, f, t, wins, valid, n, cells, order);  // SIMD: 4 at a time
    for (; k < n; ++k) {
      const int i = order != nullptr ? order[k] : k;
      cells[i] = static_cast<uint16_t>(
          valid[i] ? WeakClassifier::cellOf(evaluateKind<K>(f, wins[i], t), K) : kLutCells);
    }
  }
  void findDistinct();

  Feature _feature[kMaxWeakClassifiers];
  WeakClassifier _weak[kMaxWeakClassifiers];
  int _m = 0;
  float _trainingError = 0.f;
  ShareTable _shares;
  // Distinct features of the weak classifiers: _distinct[u] is the first weak classifier
  // with the u-th distinct feature, _distinctOf[m] the u of weak classifier m.
  int _distinct[kMaxWeakClassifiers] = {};
  int _distinctOf[kMaxWeakClassifiers] = {};
  int _numDistinct = 0;
  // evaluateMany's scratch: the table cell of every distinct feature on every window.
  mutable uint16_t _cells[kMaxWeakClassifiers][kMaxParticles] = {};
};
// 32 x 2000 x 2 B = 128,000 B of table cells (Config.hpp's budget).
static_assert(sizeof(uint16_t[kMaxWeakClassifiers][kMaxParticles]) == 128000u,
              "evaluateMany's cells: 32 x 2000 x 2 B");
static_assert(kLutCells < 65535, "cells fit uint16_t");

}  // namespace cuetrack
