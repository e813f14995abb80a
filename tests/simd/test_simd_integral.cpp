// Every integral-image kernel this build has must match the scalar reference bit
// for bit; the reference itself is checked against brute-force rectangle sums.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "Skip.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/kernels/Integral.hpp"

namespace ig = cuetrack::integral;
using cuetrack::Rgb8;

namespace {

struct Isa {
  const char* name;
  decltype(&ig::scalar::rgb) rgb;
  decltype(&ig::scalar::depth) depth;
  decltype(&ig::scalar::gray) gray;
};

// Every kernel compiled into this build that the CPU can run, plus the dispatcher.
std::vector<Isa> kernelsUnderTest() {
  std::vector<Isa> isas;
#if defined(__x86_64__) || defined(__i386__)
  isas.push_back({"sse2", ig::sse2::rgb, ig::sse2::depth, ig::sse2::gray});
  if (ig::avx2Available()) {
    isas.push_back({"avx2", ig::avx2::rgb, ig::avx2::depth, ig::avx2::gray});
  } else {
    CUETRACK_SKIP_PART("this CPU has no AVX2: the avx2 kernels are not tested here");
  }
#endif
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
  isas.push_back({"neon", ig::neon::rgb, ig::neon::depth, ig::neon::gray});
#endif
  isas.push_back({"dispatch", ig::rgb, ig::depth, ig::gray});
  return isas;
}

constexpr uint32_t kSentinel = 0xDEADBEEFu;

// One test image of each kind with padded rows, and its integral tables.
struct Case {
  int width, height, srcPad, sumPad;
  int srcStride() const { return width + srcPad; }
  int sumStride() const { return width + 1 + sumPad; }
  std::size_t srcCells() const { return static_cast<std::size_t>(srcStride()) * height + 1; }
  std::size_t sumCells() const { return static_cast<std::size_t>(sumStride()) * (height + 1); }
};

struct Tables {
  std::vector<uint32_t> gray, depth, count, gray8;
  std::vector<int32_t> alpha2, beta;
  explicit Tables(std::size_t n)
      : gray(n, kSentinel),
        depth(n, kSentinel),
        count(n, kSentinel),
        gray8(n, kSentinel),
        alpha2(n, static_cast<int32_t>(kSentinel)),
        beta(n, static_cast<int32_t>(kSentinel)) {}
  bool operator==(const Tables& o) const {
    return gray == o.gray && depth == o.depth && count == o.count && gray8 == o.gray8 &&
           alpha2 == o.alpha2 && beta == o.beta;
  }
};

uint16_t randomDepthMm(std::mt19937& rng) {
  switch (rng() % 8) {
    case 0:
      return 0;  // hole
    case 1:
      return static_cast<uint16_t>(cuetrack::kMaxDepthMm);  // edge: valid
    case 2:
      return static_cast<uint16_t>(cuetrack::kMaxDepthMm + 1);  // edge: invalid
    case 3:
      return static_cast<uint16_t>(rng());  // anything, often > max
    default:
      return static_cast<uint16_t>(1 + rng() % cuetrack::kMaxDepthMm);
  }
}

struct Images {
  // One spare element in front so rows start misaligned (offset 1 element).
  std::vector<Rgb8> rgb;
  std::vector<uint16_t> depthMm;
  std::vector<uint8_t> gray;
  Images(const Case& c, std::mt19937& rng)
      : rgb(c.srcCells()), depthMm(c.srcCells()), gray(c.srcCells()) {
    for (auto& p : rgb)
      p = {static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng())};
    for (auto& d : depthMm) d = randomDepthMm(rng);
    for (auto& g : gray) g = static_cast<uint8_t>(rng());
  }
};

Tables run(const Isa& isa, const Case& c, const Images& im) {
  Tables t(c.sumCells());
  isa.rgb(im.rgb.data() + 1, c.srcStride(), c.width, c.height, t.gray.data(), t.alpha2.data(),
          t.beta.data(), c.sumStride());
  isa.depth(im.depthMm.data() + 1, c.srcStride(), c.width, c.height, t.depth.data(), t.count.data(),
            c.sumStride());
  isa.gray(im.gray.data() + 1, c.srcStride(), c.width, c.height, t.gray8.data(), c.sumStride());
  return t;
}

const Isa kScalar{"scalar", ig::scalar::rgb, ig::scalar::depth, ig::scalar::gray};

void checkAllKernels(const Case& c, std::mt19937& rng) {
  const Images im(c, rng);
  const Tables ref = run(kScalar, c, im);
  // The row padding of the tables is never written.
  for (int y = 0; y <= c.height; ++y) {
    for (int x = c.width + 1; x < c.sumStride(); ++x) {
      REQUIRE(ref.gray[static_cast<std::size_t>(y) * c.sumStride() + x] == kSentinel);
    }
  }
  for (const Isa& isa : kernelsUnderTest()) {
    INFO(isa.name << " " << c.width << "x" << c.height << " srcPad " << c.srcPad << " sumPad "
                  << c.sumPad);
    CHECK(run(isa, c, im) == ref);
  }
}

template <typename T>
T bruteForce(const std::vector<T>& perPixel, int width, int x0, int y0, int x1, int y1) {
  T s = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      s = static_cast<T>(s + perPixel[static_cast<std::size_t>(y) * width + x]);
  return s;
}

}  // namespace

TEST_CASE("every SIMD integral kernel matches scalar on odd and small sizes", "[simd]") {
  std::mt19937 rng(12345);
  const int widths[] = {1,  2,  3,  4,  5,  6,  7,  8,  9,  11, 15,  16,  17,
                        23, 24, 25, 31, 32, 33, 47, 63, 64, 65, 100, 127, 129};
  for (int w : widths) {
    for (int h : {1, 2, 3, 7}) {
      checkAllKernels({w, h, 0, 0}, rng);
      checkAllKernels({w, h, 1 + static_cast<int>(rng() % 13), 1 + static_cast<int>(rng() % 7)},
                      rng);
    }
  }
}

TEST_CASE("every SIMD integral kernel matches scalar up to 641x481", "[simd]") {
  std::mt19937 rng(777);
  const Case cases[] = {{640, 480, 0, 0}, {641, 481, 0, 0},  {639, 479, 3, 0},
                        {641, 481, 7, 9}, {320, 240, 0, 31}, {160, 120, 5, 5},
                        {1, 481, 0, 0},   {641, 1, 0, 0},    {633, 17, 1, 2}};
  for (const Case& c : cases) checkAllKernels(c, rng);
  for (int i = 0; i < 12; ++i) {
    const Case c{1 + static_cast<int>(rng() % 641), 1 + static_cast<int>(rng() % 481),
                 static_cast<int>(rng() % 20), static_cast<int>(rng() % 20)};
    checkAllKernels(c, rng);
  }
}

TEST_CASE("an empty image gives a zero top row and touches nothing else", "[simd]") {
  for (const Isa& isa : kernelsUnderTest()) {
    INFO(isa.name);
    std::vector<uint32_t> g(8, kSentinel), d(8, kSentinel), n(8, kSentinel), g8(8, kSentinel);
    std::vector<int32_t> a(8, 7), b(8, 7);
    const Rgb8 px{1, 2, 3};
    const uint16_t mm = 5;
    const uint8_t v = 9;
    isa.rgb(&px, 0, 3, 0, g.data(), a.data(), b.data(), 4);
    isa.depth(&mm, 0, 3, 0, d.data(), n.data(), 4);
    isa.gray(&v, 0, 3, 0, g8.data(), 4);
    for (int i = 0; i < 4; ++i) {
      CHECK(g[i] == 0);
      CHECK(a[i] == 0);
      CHECK(d[i] == 0);
      CHECK(n[i] == 0);
      CHECK(g8[i] == 0);
    }
    CHECK(g[4] == kSentinel);
    CHECK(g8[4] == kSentinel);
  }
}

TEST_CASE("rectSum equals brute-force sums of the per-pixel channel values", "[simd]") {
  std::mt19937 rng(4242);
  const int w = 37, h = 23, st = w + 1;
  std::vector<Rgb8> rgb(static_cast<std::size_t>(w) * h);
  std::vector<uint16_t> depthMm(rgb.size());
  std::vector<uint8_t> gray8(rgb.size());
  std::vector<uint32_t> pxGray(rgb.size()), pxDepth(rgb.size()), pxCount(rgb.size()),
      pxGray8(rgb.size());
  std::vector<int32_t> pxAlpha2(rgb.size()), pxBeta(rgb.size());
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    rgb[i] = {static_cast<uint8_t>(rng()), static_cast<uint8_t>(rng()),
              static_cast<uint8_t>(rng())};
    depthMm[i] = randomDepthMm(rng);
    gray8[i] = static_cast<uint8_t>(rng());
    // The channel definitions, written out independently of the kernels.
    const double exactGray = 0.30078125 * rgb[i].r + 0.5859375 * rgb[i].g + 0.11328125 * rgb[i].b;
    pxGray[i] = static_cast<uint32_t>(exactGray + 0.5);  // 77/256, 150/256, 29/256, rounded
    pxAlpha2[i] = 2 * rgb[i].r - rgb[i].g - rgb[i].b;
    pxBeta[i] = rgb[i].g - rgb[i].b;
    const bool valid = depthMm[i] != 0 && depthMm[i] <= cuetrack::kMaxDepthMm;
    pxDepth[i] = valid ? depthMm[i] : 0;
    pxCount[i] = valid ? 1 : 0;
    pxGray8[i] = gray8[i];
  }
  const std::size_t cells = static_cast<std::size_t>(st) * (h + 1);
  std::vector<uint32_t> tGray(cells), tDepth(cells), tCount(cells), tGray8(cells);
  std::vector<int32_t> tAlpha2(cells), tBeta(cells);
  ig::rgb(rgb.data(), w, w, h, tGray.data(), tAlpha2.data(), tBeta.data(), st);
  ig::depth(depthMm.data(), w, w, h, tDepth.data(), tCount.data(), st);
  ig::gray(gray8.data(), w, w, h, tGray8.data(), st);

  for (int i = 0; i < 400; ++i) {
    int x0 = static_cast<int>(rng() % (w + 1)), x1 = static_cast<int>(rng() % (w + 1));
    int y0 = static_cast<int>(rng() % (h + 1)), y1 = static_cast<int>(rng() % (h + 1));
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    if (i == 0) x0 = y0 = 0, x1 = w, y1 = h;  // whole image
    INFO("rect [" << x0 << "," << x1 << ") x [" << y0 << "," << y1 << ")");
    CHECK(ig::rectSum(tGray.data(), st, x0, y0, x1, y1) == bruteForce(pxGray, w, x0, y0, x1, y1));
    CHECK(ig::rectSum(tAlpha2.data(), st, x0, y0, x1, y1) ==
          bruteForce(pxAlpha2, w, x0, y0, x1, y1));
    CHECK(ig::rectSum(tBeta.data(), st, x0, y0, x1, y1) == bruteForce(pxBeta, w, x0, y0, x1, y1));
    CHECK(ig::rectSum(tDepth.data(), st, x0, y0, x1, y1) == bruteForce(pxDepth, w, x0, y0, x1, y1));
    CHECK(ig::rectSum(tCount.data(), st, x0, y0, x1, y1) == bruteForce(pxCount, w, x0, y0, x1, y1));
    CHECK(ig::rectSum(tGray8.data(), st, x0, y0, x1, y1) == bruteForce(pxGray8, w, x0, y0, x1, y1));
  }
}

TEST_CASE("accumulators hold the largest sums without wrapping", "[simd]") {
  std::vector<Isa> isas = kernelsUnderTest();
  isas.insert(isas.begin(), kScalar);
  for (const int w : {640, 641}) {
    const int h = w == 640 ? 480 : 481, st = w + 1;
    const uint64_t n = static_cast<uint64_t>(w) * h;
    const std::size_t cells = static_cast<std::size_t>(st) * (h + 1), last = cells - 1;
    std::vector<uint32_t> g(cells), d(cells), c(cells);
    std::vector<int32_t> a(cells), b(cells);
    struct RgbCase {
      Rgb8 px;
      int64_t gray, alpha2, beta;  // per pixel
    };
    const RgbCase rgbCases[] = {{{255, 255, 255}, 255, 0, 0},
                                {{255, 0, 0}, 77, 510, 0},  // largest alpha2
                                {{0, 0, 255}, 29, -255, -255},
                                {{0, 255, 0}, 149, -255, 255},   // (150*255+128)>>8
                                {{0, 255, 255}, 178, -510, 0}};  // most negative alpha2
    for (const RgbCase& rc : rgbCases) {
      const std::vector<Rgb8> img(static_cast<std::size_t>(n), rc.px);
      for (const Isa& isa : isas) {
        INFO(isa.name << " " << w << "x" << h << " rgb " << int(rc.px.r) << "," << int(rc.px.g)
                      << "," << int(rc.px.b));
        isa.rgb(img.data(), w, w, h, g.data(), a.data(), b.data(), st);
        CHECK(g[last] == static_cast<uint32_t>(rc.gray * static_cast<int64_t>(n)));
        CHECK(a[last] == rc.alpha2 * static_cast<int64_t>(n));
        CHECK(b[last] == rc.beta * static_cast<int64_t>(n));
      }
    }
    struct DepthCase {
      uint16_t mm;
      uint32_t valid;
    };
    const DepthCase depthCases[] = {{cuetrack::kMaxDepthMm, 1},
                                    {static_cast<uint16_t>(cuetrack::kMaxDepthMm + 1), 0},
                                    {65535, 0},
                                    {0, 0}};
    for (const DepthCase& dc : depthCases) {
      const std::vector<uint16_t> img(static_cast<std::size_t>(n), dc.mm);
      for (const Isa& isa : isas) {
        INFO(isa.name << " " << w << "x" << h << " depth " << dc.mm);
        isa.depth(img.data(), w, w, h, d.data(), c.data(), st);
        // 641 x 481 x 10,000 = 3,083,210,000: above INT32_MAX, below 2^32.
        CHECK(d[last] == static_cast<uint64_t>(dc.mm) * dc.valid * n);
        CHECK(c[last] == dc.valid * n);
      }
    }
    const std::vector<uint8_t> white(static_cast<std::size_t>(n), 255);
    for (const Isa& isa : isas) {
      INFO(isa.name << " gray all 255");
      isa.gray(white.data(), w, w, h, g.data(), st);
      CHECK(g[last] == 255u * n);
    }
  }
}
