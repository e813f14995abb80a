// Portable math and the RNG: accuracy against libm, and exact repeatability.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/base/Rng.hpp"

using namespace cuetrack;

TEST_CASE("fastLog and fastExp match libm closely", "[core][math]") {
  for (float x = 1e-4f; x < 1e5f; x *= 1.37f) {
    REQUIRE(fmath::fastLog(x) == Approx(std::log(x)).margin(2e-6).epsilon(2e-6));
  }
  for (float x = -80.f; x < 80.f; x += 0.731f) {
    REQUIRE(fmath::fastExp(x) == Approx(std::exp(x)).epsilon(1e-6));
  }
  REQUIRE(fmath::fastLog(0.f) < -80.f);
}

TEST_CASE("fastAtan2 covers the full circle in [0, 2 pi)", "[core][math]") {
  for (int i = 0; i < 720; ++i) {
    const float a = static_cast<float>(i) * 0.5f * 3.14159265f / 180.f;
    const float x = 3.f * std::cos(a), y = 3.f * std::sin(a);
    float ref = std::atan2(y, x);
    if (ref < 0.f) ref += 2.f * 3.14159265f;
    const float got = fmath::fastAtan2(y, x);
    REQUIRE(got >= 0.f);
    REQUIRE(got < fmath::kTwoPi);
    float d = std::fabs(got - ref);
    if (d > 3.f) d = std::fabs(d - fmath::kTwoPi);  // wrap at 0
    REQUIRE(d < 2e-5f);
  }
  REQUIRE(fmath::fastAtan2(0.f, 0.f) == 0.f);
}

TEST_CASE("Rng repeats for a seed and differs between seeds", "[core][math]") {
  Rng a(42), b(42), c(43);
  int same = 0;
  for (int i = 0; i < 1000; ++i) {
    const uint32_t x = a.next();
    REQUIRE(x == b.next());
    same += x == c.next() ? 1 : 0;
  }
  REQUIRE(same < 5);
}

TEST_CASE("Rng is PCG32 XSH-RR: the reference implementation's demo sequence", "[core][math]") {
  // pcg32-demo (O'Neill's pcg-c-basic) seeds pcg32_srandom_r(&rng, 42, 54) and prints
  // these first six outputs; any change to the generator breaks every seed's replay.
  Rng r;
  r.reseed(42u, 54u);
  const uint32_t want[6] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                            0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
  for (uint32_t w : want) CHECK(r.next() == w);
}

TEST_CASE("Rng gaussian has zero mean and unit variance; uniform is in [0, 1)", "[core][math]") {
  Rng r(7);
  const int n = 200000;
  for (int fast = 0; fast < 2; ++fast) {
    double s = 0, s2 = 0, s4 = 0;
    for (int i = 0; i < n; ++i) {
      const double g = fast ? r.gaussianFast() : r.gaussian();
      s += g;
      s2 += g * g;
      s4 += g * g * g * g;
    }
    REQUIRE(s / n == Approx(0.0).margin(0.01));
    REQUIRE(s2 / n == Approx(1.0).epsilon(0.02));
    REQUIRE(s4 / n == Approx(fast ? 2.7 : 3.0).epsilon(0.05));  // Irwin-Hall(4): 3 - 1.2/4
  }
  float lo = 1.f, hi = 0.f;
  for (int i = 0; i < 100000; ++i) {
    const float u = r.uniform();
    lo = u < lo ? u : lo;
    hi = u > hi ? u : hi;
  }
  REQUIRE(lo >= 0.f);
  REQUIRE(hi < 1.f);
  REQUIRE(lo < 0.001f);
  REQUIRE(hi > 0.999f);
}
