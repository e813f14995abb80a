// The 2D estimate's smoother: the size filter.
#include <catch2/catch.hpp>
#include <cmath>

#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/cues/SizeFilter.hpp"

using namespace cuetrack;

namespace {

float sizeError(const Box& a, const Box& b) {
  return std::fabs(std::log(a.w / b.w)) + std::fabs(std::log(a.h / b.h));
}

}  // namespace

TEST_CASE("the size filter damps jitter and follows a steady zoom", "[core][estimate]") {
  SizeFilter2d f;
  f.configure(0.3f, 0.05f);
  REQUIRE(f.enabled());
  const Box start{50.f, 40.f, 40.f, 60.f};
  f.reset(start);
  // Jitter of +-6% around a fixed size: the filtered sizes err about half as much.
  Rng r(3);
  float worstIn = 0.f, worstOut = 0.f;
  for (int i = 0; i < 200; ++i) {
    const float s = std::exp(0.06f * r.gaussian());
    const Box in{start.x, start.y, start.w * s, start.h * s};
    const Box out = f.filter(in);
    // The centre is kept.
    CHECK(out.x + 0.5f * out.w == Approx(in.x + 0.5f * in.w).margin(1e-3));
    CHECK(out.y + 0.5f * out.h == Approx(in.y + 0.5f * in.h).margin(1e-3));
    if (i >= 20) {
      worstIn += sizeError(in, start);
      worstOut += sizeError(out, start);
    }
  }
  CHECK(worstOut < 0.7f * worstIn);
  // A steady zoom of 1% a frame: after settling, no lag (the rate term).
  f.reset(start);
  Box out{};
  for (int i = 1; i <= 120; ++i) {
    const float s = std::exp(0.01f * static_cast<float>(i));
    out = f.filter(Box{start.x, start.y, start.w * s, start.h * s});
  }
  CHECK(std::log(out.w / start.w) == Approx(1.2f).margin(0.01f));
  // Off (alpha 1) is what the presets without it rely on.
  SizeFilter2d off;
  off.configure(1.f, 0.f);
  CHECK_FALSE(off.enabled());
}
