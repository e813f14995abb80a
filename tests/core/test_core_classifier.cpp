// Weak classifiers and GentleBoost learn separable synthetic examples and
// generalise to held-back ones.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "cuetrack/core/model/IntegralChannels.hpp"
#include "cuetrack/core/model/StrongClassifier.hpp"
#include "cuetrack/core/model/TrainingSet.hpp"
#include "cuetrack/core/model/WeakClassifier.hpp"

using namespace cuetrack;

namespace {

Response resp(float angle, float mag) {
  Response r;
  r.x = mag * std::cos(angle);
  r.y = mag * std::sin(angle);
  r.valid = true;
  return r;
}

// Positives: gradients near 1 rad with magnitude ~30; negatives: either the opposite
// orientation or the same orientation but weak (~4): orientation and magnitude matter.
Response sample(bool positive, Rng& r) {
  if (positive) return resp(1.f + 0.3f * r.gaussian(), 30.f * fmath::fastExp(0.2f * r.gaussian()));
  if (r.below(2) == 0)
    return resp(1.f + 3.14159f + 0.3f * r.gaussian(), 30.f * fmath::fastExp(0.3f * r.gaussian()));
  return resp(1.f + 0.3f * r.gaussian(), 4.f * fmath::fastExp(0.2f * r.gaussian()));
}

}  // namespace

TEST_CASE("encode splits a response between the right bins", "[core][weak]") {
  // Strong gradient exactly between outer bins 0 and 1 (bin centres at 22.5 and 67.5 deg).
  const Code c = encode(resp(45.f * 3.14159265f / 180.f, 100.f), FeatureKind::Gray);
  REQUIRE(c.valid());
  REQUIRE(c.binA == 1);
  REQUIRE(c.binB == 2);
  REQUIRE(c.wCentre == Approx(0.f));
  REQUIRE(c.wA == Approx(0.5f).margin(1e-4));
  REQUIRE(c.wB == Approx(0.5f).margin(1e-4));
  // Depth: 125 mm is halfway between 50 and 200 mm: half centre, half outer.
  const Code d = encode(resp(0.3927f, 125.f), FeatureKind::Depth);
  REQUIRE(d.wCentre == Approx(0.5f).margin(1e-4));
  REQUIRE(d.wA + d.wB == Approx(0.5f).margin(1e-4));
  // Below the inner threshold: all centre. Colour: chroma 0.5 < 1.
  const Code e = encode(resp(2.f, 0.5f), FeatureKind::Colour);
  REQUIRE(e.wCentre == Approx(1.f));
  // The angle sector is floor(atan2 / (2 pi / 32)) except within ~1 deg of an edge.
  int agree = 0;
  for (int i = 0; i < 3200; ++i) {
    const float a = (static_cast<float>(i) + 0.37f) * (6.2831853f / 3200.f);
    const int got = angleIndex(3.f * std::cos(a), 3.f * std::sin(a));
    const int want = static_cast<int>(a / (6.2831853f / 32.f));
    const int diff = (got - want + 32) % 32;
    REQUIRE((diff == 0 || diff == 1 || diff == 31));
    agree += diff == 0 ? 1 : 0;
  }
  REQUIRE(agree > 3200 * 9 / 10);
  // Quantised magnitudes are monotonic and a quarter octave apart.
  for (int i = 1; i < kLutMags; ++i) {
    REQUIRE(magOfIndex(i, FeatureKind::Gray) > magOfIndex(i - 1, FeatureKind::Gray));
    REQUIRE(magIndex(magOfIndex(i, FeatureKind::Gray), FeatureKind::Gray) == i);
  }
}

TEST_CASE("a weak classifier learns orientation and magnitude and generalises", "[core][weak]") {
  constexpr int n = 120;
  Code codes[n];
  float w[n];
  int8_t y[n];
  Rng r(5);
  for (int i = 0; i < n; ++i) {
    y[i] = i % 2 == 0 ? 1 : -1;
    codes[i] = encode(sample(y[i] > 0, r), FeatureKind::Gray);
    w[i] = 1.f / n;
  }
  WeakClassifier wc;
  wc.fit(codes, w, y, n, FeatureKind::Gray);
  int correct = 0;
  const int held = 1000;
  for (int i = 0; i < held; ++i) {
    const bool pos = i % 2 == 0;
    const float f = wc.predict(sample(pos, r));
    REQUIRE(f >= -1.f);
    REQUIRE(f <= 1.f);
    correct += (pos ? f > 0.f : f < 0.f) ? 1 : 0;
  }
  REQUIRE(correct > held * 95 / 100);
  // Code and Response paths agree.
  const Response x = sample(true, r);
  REQUIRE(wc.predict(x) == wc.predict(encode(x, FeatureKind::Gray)));
  // The no-measurement bin learns its own answer.
  Code inv[4];
  float wi[4] = {0.25f, 0.25f, 0.25f, 0.25f};
  int8_t yi[4] = {1, 1, -1, -1};
  inv[0] = encode(Response{}, FeatureKind::Depth);
  inv[1] = inv[0];
  inv[2] = encode(resp(1.f, 300.f), FeatureKind::Depth);
  inv[3] = inv[2];
  WeakClassifier wd;
  wd.fit(inv, wi, yi, 4, FeatureKind::Depth);
  REQUIRE(wd.predict(Response{}) > 0.9f);
  REQUIRE(wd.predict(resp(1.f, 300.f)) < -0.9f);
}

TEST_CASE("a weak classifier still ranks responses the negatives never reach", "[core][weak]") {
  // Positives: gradients at 1 rad, magnitude ~30; negatives: the same orientation, weak
  // (~4). Without a density floor the negatives' lognormal underflows beside the
  // positives' mode, so f is exactly +1 there and over a wide band around it: the mode and
  // a response 1.5x stronger vote alike, and windows near the target and on part of it
  // score the same c = 1 (docs/algorithm.md). With the floor, f still falls off the mode,
  // and far from both classes it tends to their balance in those bins.
  constexpr int n = 100;
  Code codes[n];
  float w[n];
  int8_t y[n];
  Rng r(9);
  for (int i = 0; i < n; ++i) {
    y[i] = i < n / 2 ? 1 : -1;
    const float mag = (y[i] > 0 ? 30.f : 4.f) * fmath::fastExp(0.1f * r.gaussian());
    codes[i] = encode(resp(1.f + 0.05f * r.gaussian(), mag), FeatureKind::Gray);
    w[i] = 1.f / n;
  }
  WeakClassifier wc;
  wc.fit(codes, w, y, n, FeatureKind::Gray);
  const float f30 = wc.predict(resp(1.f, 30.f)), f45 = wc.predict(resp(1.f, 45.f));
  const float f60 = wc.predict(resp(1.f, 60.f)), f240 = wc.predict(resp(1.f, 240.f));
  INFO("f at magnitude 30 " << f30 << ", 45 " << f45 << ", 60 " << f60 << ", 240 " << f240);
  REQUIRE(wc.predict(resp(1.f, 4.f)) < -0.9f);
  REQUIRE(f30 > 0.9f);
  REQUIRE(f30 < 1.f);  // not saturated
  REQUIRE(f30 > f45 + 1e-3f);
  REQUIRE(f45 > f60 + 1e-3f);
  // All outer-bin: positives' share 1, negatives' ~0.25 of their (equal) weight.
  REQUIRE(f240 == Approx(0.6f).margin(0.1f));
}

TEST_CASE("binned error ranks an informative feature above a useless one", "[core][weak]") {
  constexpr int n = 100;
  Code good[n], bad[n];
  float w[n];
  int8_t y[n];
  Rng r(8);
  for (int i = 0; i < n; ++i) {
    y[i] = i % 2 == 0 ? 1 : -1;
    good[i] = encode(sample(y[i] > 0, r), FeatureKind::Gray);
    bad[i] = encode(resp(r.uniform(0.f, 6.28f), 20.f), FeatureKind::Gray);
    w[i] = 1.f / n;
  }
  const float eg = WeakClassifier::binnedError(good, w, y, n);
  {
    // The split form (positives first) gives the same error.
    Code sorted[n];
    float ws[n];
    int k = 0;
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i < n; ++i)
        if ((y[i] > 0) == (pass == 0)) {
          sorted[k] = good[i];
          ws[k++] = w[i];
        }
    REQUIRE(WeakClassifier::binnedErrorSplit(sorted, ws, n / 2, n) == Approx(eg).epsilon(1e-5));
  }
  const float eb = WeakClassifier::binnedError(bad, w, y, n);
  REQUIRE(eg < 0.5f * eb);
  REQUIRE(eb <= 1.0001f);
  REQUIRE(eg >= 0.f);
}

TEST_CASE("binnedErrorSplit4 is binnedErrorSplit bit for bit, rows anywhere", "[core][weak]") {
  constexpr int n = 37, split = 11;  // odd sizes
  Rng r(21);
  static Code rows[4][n];  // one row apart from the others below
  Code apart[n];
  float w[n];
  for (int i = 0; i < n; ++i) {
    w[i] = r.uniform(0.f, 0.05f);
    for (int k = 0; k < 4; ++k) {
      Response x = sample(i < split, r);
      if (r.below(7) == 0) x = Response{};  // some invalid responses
      rows[k][i] = encode(x, static_cast<FeatureKind>(k % kNumFeatureKinds));
    }
    apart[i] = rows[2][i];
  }
  const Code* const codes[4] = {rows[0], rows[1], apart, rows[3]};
  float e4[4];
  WeakClassifier::binnedErrorSplit4(codes, w, split, n, e4);
  for (int k = 0; k < 4; ++k) {
    const float e = WeakClassifier::binnedErrorSplit(codes[k], w, split, n);
    REQUIRE(std::memcmp(&e, &e4[k], sizeof e) == 0);
  }
}

namespace {

constexpr int W = 64, H = 64;
Rgb8 image[W * H];
IntegralChannels channels;
FeaturePool pool;
TrainingSet set;
ResponseCache cache;
StrongClassifier strong;

// A textured background; positives additionally carry an object: a red square
// with a bright left and dark right half inside the window [16, 48)^2.
void render(uint32_t seed, bool withObject) {
  Rng r(seed);
  for (int i = 0; i < W * H; ++i) {
    const uint8_t v = static_cast<uint8_t>(60 + r.below(120));
    const uint8_t c = static_cast<uint8_t>(r.below(40));
    image[i] = Rgb8{static_cast<uint8_t>(v - c / 2), v, static_cast<uint8_t>(v - c / 2 + c)};
  }
  if (!withObject) return;
  for (int y = 20; y < 44; ++y)
    for (int x = 20; x < 44; ++x) {
      const uint8_t v = static_cast<uint8_t>((x < 32 ? 200 : 60) + r.below(30));
      image[y * W + x] =
          Rgb8{static_cast<uint8_t>(v), static_cast<uint8_t>(v / 4), static_cast<uint8_t>(v / 4)};
    }
}

float score(uint32_t seed, bool withObject) {
  render(seed, withObject);
  Frame f;
  f.rgb = RgbView{image, W, H, W};
  channels.compute(f, PixelRect{0, 0, W, H}, false);
  const Box win{16.f + static_cast<float>(seed % 3), 16.f, 32.f, 32.f};
  return strong.evaluate(channels.tables(), win);
}

// A fresh pool (from `poolSeed`) and a set of 60 windows [16, 48)^2, every 4th positive
// (the set keeps a quarter positives); draw(i, positive) renders example i.
template <typename Draw>
void fillSet(uint64_t poolSeed, Draw draw) {
  Rng rng(poolSeed);
  REQUIRE(pool.build(true, false, true, FeatureSampling::Sparse, rng));
  set.reset(60);
  Frame f;
  f.rgb = RgbView{image, W, H, W};
  for (int i = 0; i < 60; ++i) {
    const bool pos = i % 4 == 0;
    draw(i, pos);
    channels.compute(f, PixelRect{0, 0, W, H}, false);
    const int slot = set.add(channels.tables(), Box{16.f, 16.f, 32.f, 32.f}, pos);
    cache.refreshExample(slot, pool, set);
  }
}

}  // namespace

TEST_CASE("GentleBoost separates object windows from background and generalises", "[core][boost]") {
  fillSet(1, [](int i, bool pos) { render(100 + static_cast<uint32_t>(i), pos); });
  REQUIRE(set.numPositives() == 15);
  REQUIRE(set.numNegatives() == 45);
  static float errors[kMaxPoolFeatures];
  REQUIRE(strong.train(pool, cache, set, 12, errors));
  REQUIRE(strong.size() == 12);
  REQUIRE(strong.trainingError() == Approx(0.f).margin(1e-6));
  // Held-back windows, new noise.
  int correct = 0;
  for (uint32_t s = 1000; s < 1040; ++s) {
    const bool pos = s % 2 == 0;
    const float c = score(s, pos);
    REQUIRE(c >= -1.f);
    REQUIRE(c <= 1.f);
    correct += (pos ? c > 0.f : c < 0.f) ? 1 : 0;
  }
  REQUIRE(correct >= 38);
  // Rounds pick different features with useful (below-chance) error.
  float best = 1.f;
  for (int i = 0; i < pool.size(); ++i) best = errors[i] < best ? errors[i] : best;
  REQUIRE(best < 0.3f);
  // No positives: training refuses.
  TrainingSet empty;
  empty.reset(20);
  REQUIRE_FALSE(strong.train(pool, cache, empty, 5, errors));
}

namespace {
bool sameFeature(const Feature& a, const Feature& b) {
  return a.kind == b.kind && a.x == b.x && a.y == b.y && a.w == b.w && a.h == b.h;
}
int distinctFeatures(const StrongClassifier& s) {
  int d = 0;
  for (int i = 0; i < s.size(); ++i) {
    bool seen = false;
    for (int j = 0; j < i; ++j) seen = seen || sameFeature(s.feature(i), s.feature(j));
    d += seen ? 0 : 1;
  }
  return d;
}
// Variant 0: the object (red, bright left half); 1: the same shape in green; 2: red
// without the split; 3: background only.
void renderVariant(uint32_t seed, int variant) {
  render(seed, false);
  if (variant == 3) return;
  Rng r(seed * 7 + 1);
  for (int y = 20; y < 44; ++y)
    for (int x = 20; x < 44; ++x) {
      const int base = variant == 2 ? 130 : (x < 32 ? 200 : 60);
      const uint8_t v = static_cast<uint8_t>(base + r.below(30));
      const uint8_t q = static_cast<uint8_t>(v / 4);
      image[y * W + x] = variant == 1 ? Rgb8{q, v, q} : Rgb8{v, q, q};
    }
}

}  // namespace

TEST_CASE("later boosting rounds search the candidates, re-ranked every refresh", "[core][boost]") {
  // Negatives: background, the green or the unsplit object, and (1 in 8) the object
  // itself (label noise): no single feature fits them all.
  fillSet(2, [](int i, bool pos) {
    renderVariant(200 + static_cast<uint32_t>(i),
                  pos ? 0 : (i % 8 == 2 ? 0 : (i % 4 == 1 ? 3 : 1 + (i / 4) % 2)));
  });
  REQUIRE(set.numPositives() == 15);
  static float errors[kMaxPoolFeatures];
  static StrongClassifier full, refreshed, stale, sometimes;
  REQUIRE(full.train(pool, cache, set, 12, errors, kMaxPoolFeatures));
  // One candidate, re-ranked every round: every round searches the whole pool.
  REQUIRE(refreshed.train(pool, cache, set, 12, errors, 1, 1.f, 1));
  REQUIRE(refreshed.size() == full.size());
  for (int i = 0; i < full.size(); ++i) REQUIRE(sameFeature(refreshed.feature(i), full.feature(i)));
  // One candidate, never re-ranked: every round repeats the round-0 best (control: the
  // full search does not).
  REQUIRE(stale.train(pool, cache, set, 12, errors, 1, 1.f, 0));
  REQUIRE(distinctFeatures(stale) == 1);
  REQUIRE(distinctFeatures(full) > 1);
  // Re-ranked every 4 rounds: the rounds in between repeat the last ranking's best.
  REQUIRE(sometimes.train(pool, cache, set, 12, errors, 1, 1.f, 4));
  for (int i = 0; i < sometimes.size(); ++i)
    REQUIRE(sameFeature(sometimes.feature(i), sometimes.feature(i - i % 4)));
  REQUIRE(distinctFeatures(sometimes) > 1);
  REQUIRE(distinctFeatures(sometimes) <= 3);
}
