// FixedVector (capacity in the type, a runtime size; growing past it refused), Span (a
// pointer and a count as one value) and WindowScratch (per-window scratch sized together).
#include <catch2/catch.hpp>

#include "cuetrack/core/base/FixedVector.hpp"
#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/filter/ParticleScratch.hpp"

using namespace cuetrack;

namespace {
float sum(Span<const float> s) {
  float t = 0.f;
  for (float v : s) t += v;
  return t;
}
}  // namespace

TEST_CASE("FixedVector: a size up to its capacity, refused past it", "[core][fixedvector]") {
  FixedVector<int, 3> v;
  CHECK(v.empty());
  CHECK(FixedVector<int, 3>::capacity() == 3);
  CHECK(v.push_back(1));
  CHECK(v.push_back(2));
  CHECK(v.push_back(3));
  CHECK(v.full());
  CHECK_FALSE(v.push_back(4));  // full: nothing added
  CHECK(v.size() == 3);
  CHECK(v[2] == 3);
  CHECK_FALSE(v.resize(4));  // past the capacity: the size kept
  CHECK_FALSE(v.resize(-1));
  CHECK(v.size() == 3);
  CHECK(v.resize(2));
  int total = 0;
  for (int x : v) total += x;
  CHECK(total == 3);  // 1 + 2: only the elements within the size
  v.clear();
  CHECK(v.empty());
  CHECK(v.begin() == v.end());
}

TEST_CASE("Span: a view of a count of elements, from an array, a vector or a pointer",
          "[core][fixedvector]") {
  float a[4] = {1.f, 2.f, 3.f, 4.f};
  CHECK(sum(a) == 10.f);  // a whole array
  CHECK(sum(Span<const float>(a, 2)) == 3.f);
  CHECK(sum(Span<const float>(a, -1)) == 0.f);  // a negative count is empty
  FixedVector<float, 8> v;
  v.push_back(5.f);
  v.push_back(6.f);
  Span<float> s = v.span();
  s[0] = 7.f;  // writes through to the vector
  CHECK(v[0] == 7.f);
  CHECK(sum(s) == 13.f);  // Span<float> passed as Span<const float>
  CHECK(s.first(1).size() == 1);
  CHECK(s.first(5).size() == 2);  // never past its own size
  CHECK(Span<const float>{}.empty());
}

TEST_CASE("WindowScratch: the windows, validity, scores and cue sized together",
          "[core][fixedvector]") {
  static WindowScratch<4> w;
  CHECK(w.resize(3));
  CHECK(w.boxes.size() == 3);
  CHECK(w.valid.size() == 3);
  CHECK(w.scores.size() == 3);
  CHECK(w.cue.size() == 3);
  CHECK_FALSE(w.resize(5));  // past the capacity: every size kept
  CHECK(w.size() == 3);
  CHECK(w.scores.size() == 3);
}
