// Every fit kernel this build has (FitKernels.hpp) must match the scalar reference bit
// for bit, including clamped exponents, zero densities and subnormal products.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/kernels/FitKernels.hpp"

namespace fk = cuetrack::fitk;

namespace {

struct Isa {
  const char* name;
  decltype(&fk::scalar::densRow) dens;
  decltype(&fk::scalar::bakeRow) bake;
};

std::vector<Isa> kernelsUnderTest() {
  std::vector<Isa> isas;
#if defined(CUETRACK_FITK_SSE2)
  isas.push_back({"sse2", fk::sse2::densRow, fk::sse2::bakeRow});
#endif
#if defined(CUETRACK_FITK_NEON)
  isas.push_back({"neon", fk::neon::densRow, fk::neon::bakeRow});
#endif
  isas.push_back({"dispatch", fk::densRow, fk::bakeRow});
  return isas;
}

constexpr int kN = 40;

bool sameBits(const float* a, const float* b, int n) {
  return std::memcmp(a, b, sizeof(float) * static_cast<std::size_t>(n)) == 0;
}

}  // namespace

TEST_CASE("scalar densRow is the fastExp formula", "[simd][fit]") {
  float lnm[kN], out[kN];
  for (int q = 0; q < kN; ++q) lnm[q] = -2.f + 0.3f * static_cast<float>(q);
  fk::scalar::densRow(lnm, 1.5f, -0.5f / 0.7f, 3.f, out, kN);
  for (int q = 0; q < kN; ++q) {
    const float d = lnm[q] - 1.5f;
    REQUIRE(out[q] == 3.f * cuetrack::fmath::fastExp(-0.5f / 0.7f * d * d));
  }
}

TEST_CASE("fit kernels match the scalar reference bit for bit", "[simd][fit]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  auto uni = [&](float lo, float hi) { return lo + (hi - lo) * u01(rng); };
  for (const Isa& isa : kernelsUnderTest()) {
    INFO("isa " << isa.name);
    for (int trial = 0; trial < 2000; ++trial) {
      float lnm[kN], ref[kN], got[kN];
      for (int q = 0; q < kN; ++q) lnm[q] = uni(-3.f, 12.f);
      const float mu = uni(-3.f, 12.f);
      // Variances from the prior (0.05) up; some tiny ones push exponents below -87.
      const float var = trial % 7 == 0 ? uni(1e-4f, 1e-3f) : uni(0.05f, 20.f);
      const float norm = trial % 5 == 0 ? uni(1e-30f, 1e-20f) : uni(1e-6f, 100.f);
      fk::scalar::densRow(lnm, mu, -0.5f / var, norm, ref, kN);
      isa.dens(lnm, mu, -0.5f / var, norm, got, kN);
      REQUIRE(sameBits(ref, got, kN));

      float wc[kN], wa[kN], wb[kN], d[6][kN], bref[kN], bgot[kN];
      for (int q = 0; q < kN; ++q) {
        const float t = trial % 3 == 0 ? 1.f : u01(rng), frac = u01(rng);
        wc[q] = 1.f - t;
        wa[q] = t * (1.f - frac);
        wb[q] = t * frac;
        for (int j = 0; j < 6; ++j) {
          const int kind = static_cast<int>(rng() % 4);
          d[j][q] = kind == 0 ? 0.f : (kind == 1 ? uni(1e-38f, 1e-36f) : uni(0.f, 50.f));
        }
      }
      fk::scalar::bakeRow(wc, wa, wb, d[0], d[1], d[2], d[3], d[4], d[5], 1e-7f, bref, kN);
      isa.bake(wc, wa, wb, d[0], d[1], d[2], d[3], d[4], d[5], 1e-7f, bgot, kN);
      REQUIRE(sameBits(bref, bgot, kN));
    }
  }
}
