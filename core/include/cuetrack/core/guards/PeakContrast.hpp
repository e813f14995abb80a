// Whether the estimate stands out from its surroundings (beyond the paper; with
// `lostDetection`): the classifier's score at the estimate less the mean score of the
// four windows one side away (left, right, above, below) that lie inside the image.
// A target the classifier tells from its background scores ~1 or more on this; a box
// on a plain wall, or a cloud that has drifted onto background, scores ~0 (the windows
// beside it look just the same), however confident the score at the estimate alone is.
// Such a frame counts as a miss for the lost detector and is not learnt.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

class PeakContrast {
 public:
  static constexpr int kRing = 4;
  // No ring window inside the image (a window as large as the image): nothing to compare,
  // so the estimate is taken to stand out.
  static constexpr float kNoRing = 2.f;

  // The ring around `estimate`; returns how many of out[kRing] lie inside the image.
  static int ring(const Box& estimate, int imageW, int imageH, Box out[kRing]) {
    const Box& b = estimate;
    const Box all[kRing] = {{b.x - b.w, b.y, b.w, b.h},
                            {b.x + b.w, b.y, b.w, b.h},
                            {b.x, b.y - b.h, b.w, b.h},
                            {b.x, b.y + b.h, b.w, b.h}};
    int n = 0;
    if (b.empty()) return 0;
    for (const Box& r : all)
      if (insideEnough(r, imageW, imageH)) out[n++] = r;
    return n;
  }
  // scoreAt: the classifier's score c in [-1, 1] at the estimate; the ring's scores.
  static float of(float scoreAt, Span<const float> ringScores) {
    const int n = ringScores.size();
    if (n <= 0) return kNoRing;
    float sum = 0.f;
    for (int i = 0; i < n; ++i) sum += ringScores[i];
    return scoreAt - sum / static_cast<float>(n);
  }
  // The contrast at `estimate` (score c there), the ring's windows scored by score(Box).
  template <class Score>
  static float around(const Box& estimate, int imageW, int imageH, float scoreAt, Score score) {
    Box boxes[kRing];
    float scores[kRing];
    const int k = ring(estimate, imageW, imageH, boxes);
    for (int i = 0; i < k; ++i) scores[i] = score(boxes[i]);
    return of(scoreAt, Span<const float>(scores, k));
  }
  static bool flat(float contrast) { return contrast < tuning::lost::kMinContrast; }
};

}  // namespace cuetrack
