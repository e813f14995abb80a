// The feature pool: sizes per sampling, the colour sampling distribution, and the
// pool update (worst feature of the chosen kind goes; static ones never do).
#include <catch2/catch.hpp>

#include "cuetrack/core/model/FeaturePool.hpp"

using namespace cuetrack;

TEST_CASE("pool sizes follow the sampling and the enabled kinds", "[core][pool]") {
  static FeaturePool pool;
  Rng rng(1);
  REQUIRE(pool.build(true, true, true, FeatureSampling::Sparse, rng));
  REQUIRE(pool.size() == 3 * (30 + kDynamicFeaturesPerKind));
  REQUIRE(pool.count(FeatureKind::Colour, true) == kDynamicFeaturesPerKind);
  REQUIRE(pool.count(FeatureKind::Depth, false) == 30 + kDynamicFeaturesPerKind);
  REQUIRE(pool.build(true, false, false, FeatureSampling::Dense, rng));
  REQUIRE(pool.size() == 84);
  REQUIRE(pool.count(FeatureKind::Gray, true) == 0);
  REQUIRE(pool.build(true, true, true, FeatureSampling::Dense, rng));
  REQUIRE(pool.size() == 252);
  for (int i = 0; i < pool.size(); ++i) {
    const Feature& f = pool[i];
    REQUIRE(f.isStatic);
    REQUIRE(f.x >= 0.f);
    REQUIRE(f.x + f.w <= 1.0001f);
    REQUIRE(f.y + f.h <= 1.0001f);
  }
}

TEST_CASE("colour features gather at the window centre, gradients spread", "[core][pool]") {
  Rng rng(3);
  const int n = 4000;
  double colourDist = 0, grayDist = 0;
  int colourInner = 0;
  for (int i = 0; i < n; ++i) {
    const Feature c = FeaturePool::sample(FeatureKind::Colour, rng);
    const Feature g = FeaturePool::sample(FeatureKind::Gray, rng);
    REQUIRE(c.x >= 0.f);
    REQUIRE(c.y >= 0.f);
    REQUIRE(c.x + c.w <= 1.0001f);
    REQUIRE(c.y + c.h <= 1.0001f);
    REQUIRE(g.x + g.w <= 1.0001f);
    const float cx = c.x + 0.5f * c.w - 0.5f, cy = c.y + 0.5f * c.h - 0.5f;
    const float gx = g.x + 0.5f * g.w - 0.5f, gy = g.y + 0.5f * g.h - 0.5f;
    colourDist += cx * cx + cy * cy;
    grayDist += gx * gx + gy * gy;
    colourInner += (cx * cx + cy * cy < 0.15f * 0.15f) ? 1 : 0;
  }
  REQUIRE(colourDist < 0.8 * grayDist);
  // Centre within one sigma: ~39% for a 2D Gaussian (fewer after clamping to the window).
  REQUIRE(colourInner > n * 25 / 100);
}

TEST_CASE("pool update replaces the worst dynamic feature of the chosen kind", "[core][pool]") {
  static FeaturePool pool;
  Rng rng(5);
  REQUIRE(pool.build(true, false, true, FeatureSampling::Sparse, rng));
  static float errors[kMaxPoolFeatures];
  // Gray features are poor (0.8), colour good (0.2); the worst of each kind is marked,
  // and static features carry higher errors than any dynamic one, which must never matter.
  int worstGray = -1, worstColour = -1;
  for (int i = 0; i < pool.size(); ++i) {
    const Feature& f = pool[i];
    errors[i] = f.kind == FeatureKind::Gray ? 0.8f : 0.2f;
    if (f.isStatic) errors[i] += 0.15f;
    if (!f.isStatic && f.kind == FeatureKind::Gray && worstGray < 0) worstGray = i;
    if (!f.isStatic && f.kind == FeatureKind::Colour && worstColour < 0) worstColour = i;
  }
  errors[worstGray] = 0.9f;
  errors[worstColour] = 0.3f;
  int removedGray = 0, removedColour = 0, addedColour = 0;
  for (int trial = 0; trial < 400; ++trial) {
    static FeaturePool p;
    p = pool;
    const int idx = p.update(errors, rng);
    REQUIRE(idx >= 0);
    REQUIRE(!pool[idx].isStatic);
    REQUIRE((idx == worstGray || idx == worstColour));
    REQUIRE(!p[idx].isStatic);
    removedGray += idx == worstGray ? 1 : 0;
    removedColour += idx == worstColour ? 1 : 0;
    addedColour += p[idx].kind == FeatureKind::Colour ? 1 : 0;
    for (int i = 0; i < pool.size(); ++i) {
      if (i == idx) continue;
      REQUIRE(p[i].x == pool[i].x);  // nothing else changes
    }
  }
  // Removal proportional to the mean error: gray ~0.8 vs colour ~0.2 (plus statics).
  REQUIRE(removedGray > removedColour * 2);
  // Addition proportional to 1 - mean error: colour favoured.
  REQUIRE(addedColour > 200);
}
