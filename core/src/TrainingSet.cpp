#include "cuetrack/core/TrainingSet.hpp"

namespace cuetrack {

PatchTables ExamplePatch::tables() const {
  PatchTables t;
  t.gray = gray;
  t.alpha2 = alpha2;
  t.beta = beta;
  t.depth = depth;
  t.count = count;
  t.stride = kPatchStride;
  t.width = kPatchSize;
  t.height = kPatchSize;
  return t;
}

void extractPatch(const FrameTables& t, const Box& win, ExamplePatch* out) {
  // Cell edges in table coordinates, each cell at least one pixel.
  int xs[kPatchSize + 1], ys[kPatchSize + 1];
  const float ox = win.x - static_cast<float>(t.originX);
  const float oy = win.y - static_cast<float>(t.originY);
  for (int i = 0; i <= kPatchSize; ++i) {
    const float f = static_cast<float>(i) / static_cast<float>(kPatchSize);
    int x = fmath::roundToInt(ox + f * win.w), y = fmath::roundToInt(oy + f * win.h);
    xs[i] = x < 0 ? 0 : (x > t.width ? t.width : x);
    ys[i] = y < 0 ? 0 : (y > t.height ? t.height : y);
  }
  // Column spans, the same for every row.
  int cx0[kPatchSize], cx1[kPatchSize];
  for (int i = 0; i < kPatchSize; ++i) {
    int x0 = xs[i], x1 = xs[i + 1];
    if (x1 <= x0) {
      if (x0 >= t.width) x0 = t.width - 1;
      x1 = x0 + 1;
    }
    cx0[i] = x0;
    cx1[i] = x1;
  }
  float* const gray = out->gray;
  float* const alpha2 = out->alpha2;
  float* const beta = out->beta;
  float* const depth = out->depth;
  float* const count = out->count;
  float* ch[5] = {gray, alpha2, beta, depth, count};
  for (float* c : ch)
    for (int i = 0; i < kPatchStride; ++i) c[i] = 0.f;  // top row
  for (int j = 0; j < kPatchSize; ++j) {
    int y0 = ys[j], y1 = ys[j + 1];
    if (y1 <= y0) {
      if (y0 >= t.height) y0 = t.height - 1;
      y1 = y0 + 1;
    }
    float row[5] = {0.f, 0.f, 0.f, 0.f, 0.f};
    const int base = (j + 1) * kPatchStride, prev = j * kPatchStride;
    for (int c = 0; c < 5; ++c) ch[c][base] = 0.f;
    for (int i = 0; i < kPatchSize; ++i) {
      const int x0 = cx0[i], x1 = cx1[i];
      const float inv = 1.f / static_cast<float>((x1 - x0) * (y1 - y0));
      const float v[5] = {
          detail::rect(t.gray, t.stride, x0, y0, x1, y1) * inv,
          detail::rect(t.alpha2, t.stride, x0, y0, x1, y1) * inv,
          detail::rect(t.beta, t.stride, x0, y0, x1, y1) * inv,
          detail::rect(t.depth, t.stride, x0, y0, x1, y1) * inv,
          detail::rect(t.count, t.stride, x0, y0, x1, y1) * inv,
      };
      // Written out per channel: a loop over ch[] reloads each channel's pointer.
      row[0] += v[0];
      row[1] += v[1];
      row[2] += v[2];
      row[3] += v[3];
      row[4] += v[4];
      gray[base + i + 1] = gray[prev + i + 1] + row[0];
      alpha2[base + i + 1] = alpha2[prev + i + 1] + row[1];
      beta[base + i + 1] = beta[prev + i + 1] + row[2];
      depth[base + i + 1] = depth[prev + i + 1] + row[3];
      count[base + i + 1] = count[prev + i + 1] + row[4];
    }
  }
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
  const PatchTables t = set.patch(slot).tables();
  const Box win = ExamplePatch::window();
  for (int f = 0; f < pool.size(); ++f)
    _codes[f][slot] = encode(evaluate(pool[f], win, t), pool[f].kind);
}

void ResponseCache::refreshFeature(int feature, const FeaturePool& pool, const TrainingSet& set) {
  const Box win = ExamplePatch::window();
  const Feature& f = pool[feature];
  for (int s = 0; s < set.capacity(); ++s) {
    if (!set.used(s)) continue;
    _codes[feature][s] = encode(evaluate(f, win, set.patch(s).tables()), f.kind);
  }
}

void ResponseCache::refreshAll(const FeaturePool& pool, const TrainingSet& set) {
  for (int s = 0; s < set.capacity(); ++s)
    if (set.used(s)) refreshExample(s, pool, set);
}

}  // namespace cuetrack
