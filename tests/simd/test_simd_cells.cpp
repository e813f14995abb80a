// Every cell coder this build has (CellKernels.hpp) must match the scalar reference bit
// for bit on random windows (inside, clipped, outside, tiny), odd window counts, with and
// without a visiting order, and must leave the windows it does not code alone.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "Skip.hpp"
#include "cuetrack/core/kernels/Integral.hpp"
#include "cuetrack/core/model/CellKernels.hpp"
#include "cuetrack/core/model/WeakClassifier.hpp"

namespace ck = cuetrack::cellk;
using cuetrack::Box;
using cuetrack::Feature;
using cuetrack::FeatureKind;

namespace {

struct Isa {
  const char* name;
  decltype(&ck::scalar::codeFrame) code;
};

std::vector<Isa> kernelsUnderTest() {
  std::vector<Isa> isas;
#if defined(CUETRACK_CELLK_SSE2)
  isas.push_back({"sse2", ck::sse2::codeFrame});
  if (cuetrack::integral::avx2Available()) {
    isas.push_back({"avx2", ck::avx2::codeFrame});
  } else {
    CUETRACK_SKIP_PART("this CPU has no AVX2: the avx2 cell coder is not tested here");
  }
#endif
#if defined(CUETRACK_CELLK_NEON)
  isas.push_back({"neon", ck::neon::codeFrame});
#endif
  isas.push_back({"dispatch", ck::codeFrame});
  return isas;
}

// Integral tables of a random W x H image (odd sizes, padded stride, shifted origin).
struct Tables {
  static constexpr int kW = 37, kH = 29, kStride = kW + 4;
  std::vector<uint32_t> gray, depth, count;
  std::vector<int32_t> alpha2, beta;
  cuetrack::FrameTables t;
  explicit Tables(std::mt19937& rng) {
    const std::size_t cells = static_cast<std::size_t>(kStride) * (kH + 1);
    gray.assign(cells, 0u);
    depth.assign(cells, 0u);
    count.assign(cells, 0u);
    alpha2.assign(cells, 0);
    beta.assign(cells, 0);
    std::uniform_int_distribution<int> px(0, 255);
    for (int y = 1; y <= kH; ++y)
      for (int x = 1; x <= kW; ++x) {
        const int r = px(rng), g = px(rng), b = px(rng);
        const std::size_t i = static_cast<std::size_t>(y) * kStride + static_cast<std::size_t>(x);
        const std::size_t up = i - kStride, left = i - 1, diag = i - kStride - 1;
        gray[i] = static_cast<uint32_t>((r + g + b) / 3) + gray[up] + gray[left] - gray[diag];
        alpha2[i] = (2 * r - g - b) + alpha2[up] + alpha2[left] - alpha2[diag];
        beta[i] = (g - b) + beta[up] + beta[left] - beta[diag];
      }
    t.gray = gray.data();
    t.alpha2 = alpha2.data();
    t.beta = beta.data();
    t.depth = depth.data();
    t.count = count.data();
    t.stride = kStride;
    t.width = kW;
    t.height = kH;
    t.originX = 5;
    t.originY = -3;
  }
};

}  // namespace

TEST_CASE("scalar cell coder is cellOf of evaluateKind", "[simd][cells]") {
  std::mt19937 rng(7);
  const Tables tb(rng);
  const Feature f{0.1f, 0.2f, 0.5f, 0.6f, FeatureKind::Gray, false};
  const Box wins[3] = {{8.f, 0.f, 20.f, 18.f}, {-40.f, -40.f, 10.f, 10.f}, {10.f, 2.f, 11.f, 9.f}};
  const uint8_t valid[3] = {1, 1, 0};
  uint16_t cells[3];
  REQUIRE(ck::scalar::codeFrame(FeatureKind::Gray, f, tb.t, wins, valid, 3, cells, nullptr) == 3);
  REQUIRE(cells[0] ==
          cuetrack::WeakClassifier::cellOf(
              cuetrack::evaluateKind<FeatureKind::Gray>(f, wins[0], tb.t), FeatureKind::Gray));
  REQUIRE(cells[1] == cuetrack::kLutCells);  // outside the tables: no rectangle
  REQUIRE(cells[2] == cuetrack::kLutCells);  // not a valid window
}

TEST_CASE("cell coders match the scalar reference bit for bit", "[simd][cells]") {
  std::mt19937 rng(4242);
  const Tables tb(rng);
  std::uniform_real_distribution<float> u01(0.f, 1.f);
  auto uni = [&](float lo, float hi) { return lo + (hi - lo) * u01(rng); };
  constexpr int kMaxN = 41;
  for (const Isa& isa : kernelsUnderTest()) {
    INFO("isa " << isa.name);
    for (int trial = 0; trial < 3000; ++trial) {
      const int n = 1 + trial % kMaxN;  // odd and even counts, below and above 4
      const FeatureKind kind = trial % 2 == 0 ? FeatureKind::Gray : FeatureKind::Colour;
      Feature f;
      f.kind = kind;
      f.x = uni(0.f, 0.9f);
      f.y = uni(0.f, 0.9f);
      f.w = trial % 7 == 0 ? uni(0.f, 0.02f) : uni(0.02f, 1.f - f.x);
      f.h = trial % 5 == 0 ? uni(0.f, 0.02f) : uni(0.02f, 1.f - f.y);
      std::vector<Box> wins(static_cast<std::size_t>(n));
      std::vector<uint8_t> valid(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        Box& b = wins[static_cast<std::size_t>(i)];
        const float scale = i % 9 == 0 ? 0.2f : 1.f;  // some tiny windows
        b.w = uni(0.5f, 40.f) * scale;
        b.h = uni(0.5f, 35.f) * scale;
        b.x = uni(-25.f, 45.f);  // frame px: some windows hang off the tables or miss them
        b.y = uni(-25.f, 30.f);
        valid[static_cast<std::size_t>(i)] = (i * 7 + trial) % 11 == 0 ? 0 : 1;
      }
      std::vector<uint16_t> order(static_cast<std::size_t>(n));
      std::iota(order.begin(), order.end(), uint16_t{0});
      std::shuffle(order.begin(), order.end(), rng);
      const uint16_t* ord = trial % 3 == 0 ? nullptr : order.data();
      std::vector<uint16_t> ref(static_cast<std::size_t>(n)), got(static_cast<std::size_t>(n));
      REQUIRE(ck::scalar::codeFrame(kind, f, tb.t, wins.data(), valid.data(), n, ref.data(), ord) ==
              n);
      std::fill(got.begin(), got.end(), uint16_t{0xbeef});
      const int k = isa.code(kind, f, tb.t, wins.data(), valid.data(), n, got.data(), ord);
      REQUIRE(k >= 0);
      REQUIRE(k <= n);
      REQUIRE((k % 4 == 0 || k == n));
      for (int j = 0; j < n; ++j) {
        const std::size_t i = ord != nullptr ? ord[j] : static_cast<std::size_t>(j);
        INFO("trial " << trial << " n " << n << " window " << i);
        REQUIRE(got[i] == (j < k ? ref[i] : uint16_t{0xbeef}));
      }
    }
  }
}
