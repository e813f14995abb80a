// Re-acquisition while lost (beyond the paper; with `lostDetection`). Every kEvery-th
// particle is drawn anew each frame: half anywhere in the image, half around the last
// confidently learnt estimate within a radius that grows with the frames lost; the rest
// of the cloud keeps following the best candidate so that the lost detector can confirm
// it. A fresh window scores high only within a few % of the reappeared target's window,
// so with `refineSearch` the best few climb to their score's peak before weighing.
#pragma once

#include "cuetrack/core/Config.hpp"
#include "cuetrack/core/Geometry.hpp"
#include "cuetrack/core/IntegralChannels.hpp"
#include "cuetrack/core/ParticleFilter.hpp"
#include "cuetrack/core/Rng.hpp"
#include "cuetrack/core/Tuning.hpp"

namespace cuetrack {

// The image and state space the search works in.
struct SearchView {
  bool is3d = false;
  CameraIntrinsics k{};
  int imageW = 0, imageH = 0;
  Box window(const Particle& q) const { return particleWindow(q, is3d, k); }
};

class LostSearch {
 public:
  static constexpr int kEvery = tuning::search::kEvery;
  static_assert(tuning::search::kRefineWindows <= kMaxSearchRefineWindows, "capacity");

  static bool drawsAnew(int i) { return i % kEvery == 0; }
  // Particle i's fresh draw while lost for `framesLost` frames: the last learnt estimate
  // `last` (without velocity) moved to an image point anywhere (every other one) or
  // around where it was; in 3D at its depth on the ray through that point, so that the
  // depth correction puts it on the surface there at the size the target would have.
  static Particle draw(int i, const Particle& last, int framesLost, const SearchView& view,
                       Rng& rng);
  // While searching, a window must see most of the target to re-detect it (windows half
  // outside the image score on whatever their features read there).
  static bool insideEnough(const Box& b, int imageW, int imageH) {
    const PixelRect c = clipBox(b, imageW, imageH);
    return static_cast<float>(c.width() * c.height()) >= tuning::search::kInside * b.area();
  }
  // refineSearch: the best scored fresh windows (valid ones among the first n) climb in
  // image position to a peak of score(box), staying inside `roi` (where the tables are);
  // their particles, boxes and scores are updated in place.
  template <typename ScoreFn>
  static void refine(int n, const PixelRect& roi, const SearchView& view, ParticleFilter& filter,
                     Box* boxes, float* scores, const uint8_t* valid, ScoreFn&& score);

 private:
  // Indices of the (at most kRefineWindows) best scored valid fresh windows, best first.
  static int best(int n, const float* scores, const uint8_t* valid, int* top);
};

template <typename ScoreFn>
void LostSearch::refine(int n, const PixelRect& roi, const SearchView& view, ParticleFilter& filter,
                        Box* boxes, float* scores, const uint8_t* valid, ScoreFn&& score) {
  int top[kMaxSearchRefineWindows];
  const int nt = best(n, scores, valid, top);
  for (int t = 0; t < nt; ++t) {
    const int i = top[t];
    const Box start = boxes[i];
    Box b = start;
    float s = scores[i];
    float step = tuning::search::kRefineStep;
    for (int k = 0; k < tuning::search::kRefineSteps; ++k) {
      const float dx[4] = {step * b.w, -step * b.w, 0.f, 0.f};
      const float dy[4] = {0.f, 0.f, step * b.h, -step * b.h};
      int bestMove = -1;
      float bestScore = s;
      for (int m = 0; m < 4; ++m) {
        const Box c{b.x + dx[m], b.y + dy[m], b.w, b.h};
        const PixelRect r = clipBox(c, view.imageW, view.imageH);
        if (!insideEnough(c, view.imageW, view.imageH) || r.x0 < roi.x0 || r.y0 < roi.y0 ||
            r.x1 > roi.x1 || r.y1 > roi.y1)
          continue;
        const float sc = score(c);
        if (sc > bestScore) {
          bestScore = sc;
          bestMove = m;
        }
      }
      if (bestMove < 0) {
        step *= 0.5f;
        continue;
      }
      b.x += dx[bestMove];
      b.y += dy[bestMove];
      s = bestScore;
    }
    // Move the particle by the same image shift: along x, y at its depth in 3D.
    Particle& q = filter[i];
    const float du = b.x - start.x, dv = b.y - start.y;
    if (view.is3d) {
      q.p[0] += du * q.p[2] / view.k.fx;
      q.p[1] += dv * q.p[2] / view.k.fy;
    } else {
      q.p[0] += du;
      q.p[1] += dv;
    }
    boxes[i] = view.window(q);
    scores[i] = s;
  }
}

}  // namespace cuetrack
