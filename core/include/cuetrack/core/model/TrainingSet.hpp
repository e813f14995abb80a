// The observation model's training set: up to kMaxTrainingExamples labelled
// windows. Each example is kept as the frame's integral tables sampled at the
// window's 33x33 cell edges (Features.hpp's grid), with those edges' pixel
// coordinates, so any feature, including one sampled later, reads the same pixel
// sums on an old example as it read on the frame: the same answer, bit for bit. Slot 0 holds the
// first positive (an anchor against drift); the other positives and the negatives are two FIFOs.
// ResponseCache keeps every pool feature's coded response on every example, so a training step only
// codes what changed.
#pragma once

#include <cstdint>

#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/model/FeaturePool.hpp"
#include "cuetrack/core/model/Features.hpp"
#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack {

inline constexpr int kPatchSize = kGridCells;        // cells per side
inline constexpr int kPatchStride = kPatchSize + 1;  // table cells per row
inline constexpr int kPatchCells = kPatchStride * kPatchStride;

struct ExamplePatch {
  // Integral tables over cells: entry (i, j) sums the pixels of cells [0, i) x [0, j).
  uint32_t gray[kPatchCells];
  int32_t alpha2[kPatchCells];
  int32_t beta[kPatchCells];
  uint32_t depth[kPatchCells];  // [mm], over valid pixels
  uint32_t count[kPatchCells];  // valid depth pixels
  int16_t edgeX[kPatchStride];  // pixel column of each cell edge (any common origin)
  int16_t edgeY[kPatchStride];  // pixel row of each cell edge
  PatchView view() const;
};

// Samples the tables at the cell edges of window `win` (frame px) into a patch.
void extractPatch(const FrameTables& t, const Box& win, ExamplePatch* out);

class TrainingSet {
 public:
  // capacity <= kMaxTrainingExamples; a quarter of it (at least 2) holds positives, of
  // which the first `anchors` (>= 1) are kept for good (the initial ones: against drift).
  void reset(int capacity, int anchors = 1);
  bool isAnchor(int slot) const { return slot < _anchors; }
  int positiveSlots() const { return _posCapacity; }  // slots [0, this) hold positives only
  // Adds an example, replacing the oldest of its FIFO; returns the slot written.
  int add(const FrameTables& t, const Box& win, bool positive);
  int capacity() const { return _capacity; }
  bool used(int slot) const { return _used[slot]; }
  int8_t label(int slot) const { return _label[slot]; }
  const int8_t* labels() const { return _label; }
  const ExamplePatch& patch(int slot) const { return _patch[slot]; }
  int numPositives() const;
  int numNegatives() const;

 private:
  ExamplePatch _patch[kMaxTrainingExamples];
  int8_t _label[kMaxTrainingExamples] = {};
  bool _used[kMaxTrainingExamples] = {};
  int _capacity = 0;
  int _posCapacity = 0;
  int _anchors = 1;
  int _nextPos = 0;  // next FIFO slot for positives, in [_anchors, _posCapacity)
  int _nextNeg = 0;  // next FIFO slot for negatives, in [_posCapacity, _capacity)
};
// 140 examples x (5 channels x 33^2 cells x 4 B + 2 x 33 edges x 2 B) = 3,067,680 B.
static_assert(sizeof(ExamplePatch) == 5u * kPatchCells * 4u + 2u * kPatchStride * 2u,
              "patch: 5 x 33 x 33 x 4 B tables + 2 x 33 x 2 B edges");

class ResponseCache {
 public:
  // Recodes one example (all pool features) or one feature (all used examples).
  void refreshExample(int slot, const FeaturePool& pool, const TrainingSet& set);
  void refreshFeature(int feature, const FeaturePool& pool, const TrainingSet& set);
  void refreshAll(const FeaturePool& pool, const TrainingSet& set);
  const Code* row(int feature) const { return _codes[feature]; }

 private:
  Code _codes[kMaxPoolFeatures][kMaxTrainingExamples];
};
// 256 features x 140 examples x 20 B = 716,800 B.
static_assert(sizeof(Code) == 20, "Code is 20 bytes");

}  // namespace cuetrack
