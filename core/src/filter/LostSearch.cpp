#include "cuetrack/core/filter/LostSearch.hpp"

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack {

Particle LostSearch::draw(int i, const Particle& last, int framesLost, const SearchView& view,
                          Rng& rng) {
  const bool wide = (i / kEvery) % 2 == 0;
  Particle q = last;
  q.v.setZero();
  const float iw = static_cast<float>(view.imageW), ih = static_cast<float>(view.imageH);
  float u, v;
  if (wide) {
    u = rng.uniform(0.f, iw);
    v = rng.uniform(0.f, ih);
  } else {
    const Box a = view.window(last);
    const float r =
        fmath::sqrtf(a.w * a.h) * (0.5f + tuning::search::kGrowth * static_cast<float>(framesLost));
    u = fmath::clampf(a.x + 0.5f * a.w + r * rng.gaussianFast(), 0.f, iw);
    v = fmath::clampf(a.y + 0.5f * a.h + r * rng.gaussianFast(), 0.f, ih);
  }
  if (view.is3d) {
    q.p = backProject(view.k, u, v, q.p.z());
  } else {
    const float sc = fmath::fastExp(tuning::search::kScaleNoise2d * rng.gaussianFast());
    q.p[0] = u;
    q.p[1] = v;
    q.size[0] *= sc;
    q.size[1] *= sc;
  }
  return q;
}

}  // namespace cuetrack
