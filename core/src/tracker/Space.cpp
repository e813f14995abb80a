#include "cuetrack/core/tracker/Space.hpp"

#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

void Space::configure(bool adaptsSize) {
  _adaptsSize = adaptsSize;
  _motion3d.sizeNoise = adaptsSize ? tuning::cylinder::kSizeNoise : 0.f;
  _sizeFilter.configure(tuning::size2d::kGain, tuning::size2d::kRateGain);
}

void Space::start(bool is3d, const CameraIntrinsics& k, int imageW, int imageH) {
  _is3d = is3d;
  _k = k;
  _w = imageW;
  _h = imageH;
}

Particle Space::initial(const Box& b, float surfaceMm) const {
  Particle q;
  if (_is3d) {
    q = cylinderFromBox(b, surfaceMm, _k);
  } else {
    q.p[0] = b.x + 0.5f * b.w;
    q.p[1] = b.y + 0.5f * b.h;
    q.size[0] = b.w;
    q.size[1] = b.h;
  }
  return q;
}

int Space::initialPositives() const {
  return _is3d ? tuning::training::kInitialPositives3d : tuning::training::kInitialPositives2d;
}

float Space::initialJitter() const {
  return _is3d ? tuning::training::kInitialJitter3d : tuning::training::kInitialJitter2d;
}

void Space::predict(int i, Particle& q, FastMotion& fast, Rng& rng, float dtS, float spread,
                    int framesElapsed) const {
  if (_is3d) {
    _motion3d.predict(q, rng, dtS, spread);
    fast.jump3d(i, q, _motion3d, rng, dtS);
  } else {
    _motion2d.predict(q, rng, spread, framesElapsed);
    fast.jump2d(i, q, _motion2d, rng);
  }
  keepSane(q);
}

void Space::keepSane(Particle& q) const {
  if (_is3d) {
    keepInView(q, _k, _w, _h);
    return;
  }
  // Keep windows sane and near the image.
  const Box c = sane(window(q));
  q.p[0] = c.x + 0.5f * c.w;
  q.p[1] = c.y + 0.5f * c.h;
  q.size[0] = c.w;
  q.size[1] = c.h;
}

void Space::correctDepths(bool hasDepth, float dtS, const IntegralChannels& channels,
                          const FastMotion& fast, ParticleFilter& filter, Span<Box> boxes) const {
  if (!_is3d || !hasDepth) return;
  // Pull each particle onto the measured surface (paper eq. 2).
  const int n = filter.size();
  for (int i = 0; i < n; ++i) {
    if (correctDepth(filter[i], channels, _k, dtS, _w, _h)) boxes[i] = window(filter[i]);
  }
  // A jump that landed on another surface (a twin further back, the background) is
  // undone: only the sideways search is wanted, not a new depth.
  for (int i = 1; fast.jumping() && i < n; i += FastMotion::kEvery) {
    if (!fast.undoOffSurface(i, filter[i])) continue;
    keepSane(filter[i]);
    correctDepth(filter[i], channels, _k, dtS, _w, _h);
    boxes[i] = window(filter[i]);
  }
}

const NegativeSampler::Cylinder* Space::negativesCylinder(const IntegralChannels& channels,
                                                          const Particle& last,
                                                          NegativeSampler::Cylinder* out) const {
  if (!_is3d) return nullptr;
  out->channels = &channels;
  out->k = _k;
  out->diameterMm = last.size[0];
  out->heightMm = last.size[1];
  out->imageW = _w;
  out->imageH = _h;
  return out;
}

bool Space::scorable(const Box& b, bool searching) const {
  if (b.empty() || b.w < 4.f || b.h < 4.f) return false;
  if (!searching)
    return b.x + b.w > 0.f && b.y + b.h > 0.f && b.x < static_cast<float>(_w) &&
           b.y < static_cast<float>(_h);
  return insideEnough(b);
}

void Space::report(TrackResult* r, const Particle& at, const Box& targetBox,
                   const IntegralChannels& channels) const {
  if (!_is3d) return;
  r->hasPosition3d = true;
  for (int a = 0; a < 3; ++a) r->positionMm[a] = at.p[a];
  // The inner half of the target's own box: a cylinder's or a turned box's silhouette
  // leaves background at the corners of its box. (A frame without depth has none in the
  // tables.)
  const Box& b = targetBox;
  const Box inner{b.x + 0.25f * b.w, b.y + 0.25f * b.h, 0.5f * b.w, 0.5f * b.h};
  r->depthPredicted =
      !(channels.validDepthFraction(clipBox(inner, _w, _h)) >= tuning::kMinDepthSupport);
}

Box Space::filterSize(const Box& b) {
  if (_is3d || !_sizeFilter.enabled() || b.empty()) return b;
  return _sizeFilter.filter(b);
}

}  // namespace cuetrack
