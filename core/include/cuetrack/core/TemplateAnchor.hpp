// The 2D template anchor (beyond the paper; `scaleAnchor2d`): the classifier peaks at
// whatever size and place it learnt last, so in 2D the estimate's size and centre
// random-walk with the learnt positives. The init box's grey template does not: each
// frame it is matched (NCC of 32x32 cell means) on a ladder of sizes around the
// estimate, then at small shifts, and a good match pulls the estimate part of the way
// there (docs/algorithm.md). A few dozen window reads a frame, grey table only.
#pragma once

#include "cuetrack/core/Features.hpp"
#include "cuetrack/core/Geometry.hpp"
#include "cuetrack/core/ParticleFilter.hpp"
#include "cuetrack/core/TrackerConfig.hpp"
#include "cuetrack/core/TrainingSet.hpp"
#include "cuetrack/core/Tuning.hpp"

namespace cuetrack {

class TemplateAnchor {
 public:
  struct Params {
    int scaleSteps = tuning::templateAnchor::kScaleSteps;  // <= kMaxTemplateScaleSteps
    float scaleStep = tuning::templateAnchor::kScaleStep;
    float minNcc = tuning::templateAnchor::kMinNcc;
    float gain = tuning::templateAnchor::kGain;
    float shiftStep = tuning::templateAnchor::kShiftStep;  // 0: size only
    float shiftGain = tuning::templateAnchor::kShiftGain;
  };
  static Params paramsOf(const TrackerConfig& c);

  void configure(const Params& p) { _p = p; }
  // Takes `win`'s template from the tables; false (and inactive) if the window is flat or
  // the ladder is empty.
  bool capture(const FrameTables& t, const Box& win);
  void clear() { _active = false; }
  bool active() const { return _active; }
  // The estimate with its size, then its centre, moved towards the template's best match;
  // `est` unchanged when the best match is poor (the target turned, changed or is hidden).
  Box correct(const FrameTables& t, const Box& est);
  // anchorMovesCloud: every (2D) particle shifted and rescaled by kCloudGain of the
  // correction from `from` to `to`, and its window in boxes[i] updated, so that the
  // correction stays in the state instead of being made afresh each frame to a mean the
  // classifier keeps pulling away.
  static void moveCloud(const Box& from, const Box& to, ParticleFilter& filter, Box* boxes);
  // NCC of `win`'s grey cells with the template, in [-1, 1]; -2 when `win` is flat.
  float match(const FrameTables& t, const Box& win);

 private:
  Params _p{};
  bool _active = false;
  float _anchor[kPatchSize * kPatchSize] = {};  // zero-mean, unit-norm cell means
  float _probe[kPatchSize * kPatchSize] = {};
};

}  // namespace cuetrack
