// A second appearance cue beside the boosted classifier (beyond the paper;
// `correlationCue`): a template of the target's gray level, kCells x kCells cell means of
// the window, matched by normalised cross-correlation (NCC) at every cell offset within
// kReach cells (1.5 sides) of the last estimate. The cells are box sums on the gray
// integral table, so the cost does not depend on the target's size: (kCells + 2 kReach)^2
// box sums and kOffsets^2 x kCells^2 multiply-adds a frame.
//
// Why: the classifier learns from its own estimates, and a target that moves by a side or
// more between frames leaves the cloud behind; within a few frames of windows half on
// the background the classifier no longer knows the target (docs/experiments.md, issue
// 30). A template that changes slowly, matched densely where the cloud did not look,
// still finds it. The response is a proposal (particles drawn at its peak) and a second
// term of the particles' weights.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/model/Features.hpp"

namespace cuetrack {

class CorrelationCue {
 public:
  static constexpr int kCells = 12;                  // template cells per side
  static constexpr int kReach = 18;                  // offsets per side [cells]: 1.5 sides
  static constexpr int kGrid = kCells + 2 * kReach;  // search cells per side
  static constexpr int kOffsets = 2 * kReach + 1;    // offsets per axis
  static constexpr float kNoResponse = -1.f;         // outside the map or the tables

  // The box the search reads around the window `around` (for the tables' region).
  static Box region(const Box& around) {
    constexpr float r = static_cast<float>(kReach) / static_cast<float>(kCells);
    return Box{around.x - r * around.w, around.y - r * around.h, (1.f + 2.f * r) * around.w,
               (1.f + 2.f * r) * around.h};
  }

  // The template from window `win` (false when the window's cells are not all on the
  // tables, or it is flat: nothing to correlate).
  bool reset(const FrameTables& t, const Box& win);
  // Blends window `win` into the template at `rate` (0..1); no-op where it is not whole.
  void learn(const FrameTables& t, const Box& win, float rate);

  // NCC of the template at every offset around window `around` (its size sets the
  // cells'). False without a template.
  bool search(const FrameTables& t, const Box& around);
  bool ready() const { return _ready; }
  // The best offset's response and window (after search()).
  float peak() const { return _peak; }
  Box peakBox() const { return _peakBox; }
  // The response at the offset nearest a window centred at (u, v) [px], kNoResponse
  // outside the searched map.
  float at(float u, float v) const;

 private:
  // Mean gray of the window's cells into out[kCells * kCells]; false if any is off the tables.
  static bool cells(const FrameTables& t, const Box& win, float* out);
  // _unit from _template; false (and _flat) when the template is flat.
  bool normalise();

  float _template[kCells * kCells]{};
  float _unit[kCells * kCells]{};  // the template, zero-mean and of unit norm
  bool _ready = false;             // reset() read a whole window that was not flat
  bool _flat = false;              // the template (since learnt) is flat: nothing to match
  // The last search: its grid origin and cell size [px], and the response per offset.
  float _originX = 0.f, _originY = 0.f, _cellW = 1.f, _cellH = 1.f;
  float _response[kOffsets * kOffsets]{};
  // search()'s scratch: the grid's cell means; integrals of them, of their squares and of
  // the cells off the tables (each patch's mean, spread and wholeness in O(1)).
  static constexpr int kStride = kGrid + 1;
  float _grid[kGrid * kGrid]{};
  double _sum[kStride * kStride]{};
  double _sumSq[kStride * kStride]{};
  int _off[kStride * kStride]{};
  float _peak = kNoResponse;
  Box _peakBox{};
  bool _searched = false;
};

}  // namespace cuetrack
