#include "cuetrack/core/model/TrainingSet.hpp"

namespace cuetrack {

PatchView ExamplePatch::view() const {
  PatchView v;
  v.t.gray = gray;
  v.t.alpha2 = alpha2;
  v.t.beta = beta;
  v.t.depth = depth;
  v.t.count = count;
  v.t.stride = kPatchStride;
  v.t.width = kPatchSize;
  v.t.height = kPatchSize;
  v.edgeX = edgeX;
  v.edgeY = edgeY;
  return v;
}

namespace {
// Entries (i, j) of table `in` at columns xs, rows ys, relative to (xs[0], ys[0]): the
// sum of the pixels [xs[0], xs[i]) x [ys[0], ys[j]). Exact: integral tables wrap
// modulo 2^32 and differences of them are exact (Integral.hpp).
template <typename T>
void sample(const T* in, int stride, const int* xs, const int* ys, T* out) {
  const T* r0 = in + static_cast<std::ptrdiff_t>(ys[0]) * stride;
  for (int j = 0; j < kPatchStride; ++j) {
    const T* r = in + static_cast<std::ptrdiff_t>(ys[j]) * stride;
    T* o = out + j * kPatchStride;
    const T base = static_cast<T>(r[xs[0]] - r0[xs[0]]);
    for (int i = 0; i < kPatchStride; ++i)
      o[i] = static_cast<T>(static_cast<T>(r[xs[i]] - r0[xs[i]]) - base);
  }
}
}  // namespace

void extractPatch(const FrameTables& t, const Box& win, ExamplePatch* out) {
  int xs[kPatchStride], ys[kPatchStride];
  const float ox = win.x - static_cast<float>(t.originX);
  const float oy = win.y - static_cast<float>(t.originY);
  for (int i = 0; i < kPatchStride; ++i) {
    xs[i] = gridEdge(ox, win.w, i, t.width);
    ys[i] = gridEdge(oy, win.h, i, t.height);
    out->edgeX[i] = static_cast<int16_t>(xs[i]);
    out->edgeY[i] = static_cast<int16_t>(ys[i]);
  }
  sample(t.gray, t.stride, xs, ys, out->gray);
  sample(t.alpha2, t.stride, xs, ys, out->alpha2);
  sample(t.beta, t.stride, xs, ys, out->beta);
  sample(t.depth, t.stride, xs, ys, out->depth);
  sample(t.count, t.stride, xs, ys, out->count);
}

void TrainingSet::reset(int capacity, int anchors) {
  if (capacity > kMaxTrainingExamples) capacity = kMaxTrainingExamples;
  if (capacity < 4) capacity = 4;
  _capacity = capacity;
  _posCapacity = capacity / 4 < 2 ? 2 : capacity / 4;
  if (anchors < 1) anchors = 1;
  if (anchors > _posCapacity - 1) anchors = _posCapacity - 1;
  _anchors = anchors;
  _nextPos = 0;
  _nextNeg = _posCapacity;
  for (int i = 0; i < kMaxTrainingExamples; ++i) {
    _used[i] = false;
    _label[i] = 0;
  }
}

int TrainingSet::add(const FrameTables& t, const Box& win, bool positive) {
  int slot;
  if (positive) {
    slot = _nextPos;
    _nextPos = _nextPos + 1 >= _posCapacity ? _anchors : _nextPos + 1;  // anchors are kept
  } else {
    slot = _nextNeg;
    _nextNeg = _nextNeg + 1 >= _capacity ? _posCapacity : _nextNeg + 1;
  }
  extractPatch(t, win, &_patch[slot]);
  _label[slot] = positive ? 1 : -1;
  _used[slot] = true;
  return slot;
}

int TrainingSet::numPositives() const {
  int n = 0;
  for (int i = 0; i < _capacity; ++i) n += (_used[i] && _label[i] > 0) ? 1 : 0;
  return n;
}

int TrainingSet::numNegatives() const {
  int n = 0;
  for (int i = 0; i < _capacity; ++i) n += (_used[i] && _label[i] < 0) ? 1 : 0;
  return n;
}

void ResponseCache::refreshExample(int slot, const FeaturePool& pool, const TrainingSet& set) {
  const PatchView v = set.patch(slot).view();
  for (int f = 0; f < pool.size(); ++f)
    _codes[f][slot] = encode(evaluate(pool[f], v), pool[f].kind);
}

void ResponseCache::refreshFeature(int feature, const FeaturePool& pool, const TrainingSet& set) {
  const Feature& f = pool[feature];
  for (int s = 0; s < set.capacity(); ++s) {
    if (!set.used(s)) continue;
    _codes[feature][s] = encode(evaluate(f, set.patch(s).view()), f.kind);
  }
}

void ResponseCache::refreshAll(const FeaturePool& pool, const TrainingSet& set) {
  for (int s = 0; s < set.capacity(); ++s)
    if (set.used(s)) refreshExample(s, pool, set);
}

}  // namespace cuetrack
