#include "cuetrack/core/filter/Reseeder.hpp"

namespace cuetrack {

int Reseeder::place(const Box& c, const Particle& from, float dtS, bool withVelocity,
                    const SearchView& view, const IntegralChannels& channels, Rng& rng,
                    ParticleFilter& filter) {
  const int n = filter.size();
  const float side = fmath::sqrtf(c.w * c.h);
  const float jitter = tuning::motion2d::kPositionNoise * side;
  int moved = 0;
  for (int i = kSlot; i < n; i += kEvery) {
    const float u = c.x + 0.5f * c.w + jitter * rng.gaussianFast();
    const float v = c.y + 0.5f * c.h + jitter * rng.gaussianFast();
    Particle q = from;
    if (view.is3d) {
      q.p = backProject(view.k, u, v, from.p.z());
      // Component by component with 1 / dt: Eigen's vector-by-scalar quotient runs on
      // NEON's reciprocal estimate on armhf, and the tracks would differ there.
      const float invDt = withVelocity && dtS > 0.f ? 1.f / dtS : 0.f;
      q.v[0] = (q.p[0] - from.p[0]) * invDt;
      q.v[1] = (q.p[1] - from.p[1]) * invDt;
      q.v[2] = 0.f;
      keepInView(q, view.k, view.imageW, view.imageH);
      correctDepth(q, channels, view.k, dtS, view.imageW, view.imageH);
    } else {
      q.p[0] = u;
      q.p[1] = v;
      q.v.setZero();
      if (withVelocity) {
        q.v[0] = u - from.p[0];  // px per frame
        q.v[1] = v - from.p[1];
      }
      q.size[0] = c.w;
      q.size[1] = c.h;
    }
    filter[i] = q;
    _index[moved] = static_cast<uint16_t>(i);
    _windows[moved] = view.window(q);
    ++moved;
  }
  _moved = moved;
  return moved;
}

Reseeder::Tiles Reseeder::tiles(const Box& last, float stepSides, int imageW, int imageH) {
  Tiles t;
  t.last = last;
  t.stepSides = stepSides;
  const float step = stepSides;
  t.nx = 1 + static_cast<int>((static_cast<float>(imageW) - last.w) / (step * last.w));
  t.ny = 1 + static_cast<int>((static_cast<float>(imageH) - last.h) / (step * last.h));
  return t;
}

Box Reseeder::nextTile(const Tiles& t) {
  const int tiles = t.count();
  const int k = _scanTile++ % tiles;
  if (_scanTile >= tiles) _scanTile = 0;
  const float step = t.stepSides;
  return Box{(0.5f * step + static_cast<float>(k % t.nx) * step) * t.last.w,
             (0.5f * step + static_cast<float>(k / t.nx) * step) * t.last.h, t.last.w, t.last.h};
}

}  // namespace cuetrack
