// cuetrack-microbench: times the integral-image kernels on one 640x480 frame per
// channel (median of many runs), or runs one kernel a fixed number of times with
// no clock at all so qemu-icount can count its instructions exactly.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/kernels/Integral.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

namespace cli = cuetrack::cli;
namespace ig = cuetrack::integral;
using cuetrack::Rgb8;

namespace {

struct Isa {
  const char* name;
  decltype(&ig::scalar::rgb) rgb;
  decltype(&ig::scalar::depth) depth;
  decltype(&ig::scalar::gray) gray;
};

const Isa kIsas[] = {
    {"scalar", ig::scalar::rgb, ig::scalar::depth, ig::scalar::gray},
#if defined(__x86_64__) || defined(__i386__)
    {"sse2", ig::sse2::rgb, ig::sse2::depth, ig::sse2::gray},
    {"avx2", ig::avx2::rgb, ig::avx2::depth, ig::avx2::gray},
#endif
#if defined(__ARM_NEON) || defined(__ARM_NEON__)
    {"neon", ig::neon::rgb, ig::neon::depth, ig::neon::gray},
#endif
};

constexpr int kMaxRuns = 10000;

// Frame and tables at full capacity, in static storage like the tracker's own.
Rgb8 gRgb[cuetrack::kMaxPixels];
uint16_t gDepthMm[cuetrack::kMaxPixels];
uint8_t gGray[cuetrack::kMaxPixels];
uint32_t gTableA[cuetrack::kMaxIntegralCells], gTableB[cuetrack::kMaxIntegralCells];
int32_t gTableC[cuetrack::kMaxIntegralCells], gTableD[cuetrack::kMaxIntegralCells];
uint64_t gTimesUs[kMaxRuns];

// Deterministic, Kinect-like content: textured colour, depth 0.5-8 m with ~10 % holes.
void fillFrame(int width, int height) {
  uint32_t s = 2463534242u;
  auto next = [&s] {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  };
  for (int i = 0; i < width * height; ++i) {
    const uint32_t v = next();
    gRgb[i] = {static_cast<uint8_t>(v), static_cast<uint8_t>(v >> 8),
               static_cast<uint8_t>(v >> 16)};
    gGray[i] = static_cast<uint8_t>(v >> 24);
    gDepthMm[i] = (v % 10) == 0 ? 0 : static_cast<uint16_t>(500 + (v >> 8) % 7500);
  }
}

// Runs one kernel on the frame; returns the bottom-right cell (a checksum that
// keeps the work observable and must agree across ISAs).
uint32_t runKernel(const Isa& isa, char kernel, int w, int h) {
  const int st = w + 1;
  const std::size_t last = static_cast<std::size_t>(st) * (h + 1) - 1;
  switch (kernel) {
    case 'r':
      isa.rgb(gRgb, w, w, h, gTableA, gTableC, gTableD, st);
      return gTableA[last] ^ static_cast<uint32_t>(gTableC[last]) ^
             static_cast<uint32_t>(gTableD[last]);
    case 'd':
      isa.depth(gDepthMm, w, w, h, gTableA, gTableB, st);
      return gTableA[last] ^ gTableB[last];
    default:
      isa.gray(gGray, w, w, h, gTableA, st);
      return gTableA[last];
  }
}

const char* kernelName(char k) {
  return k == 'r' ? "rgb (gray+alpha2+beta)" : k == 'd' ? "depth (sum+count)" : "gray8";
}

std::string exitCodes() {
  std::string t =
      "Timed mode prints the median and minimum time per frame of each kernel and ISA.\n"
      "--icount runs one kernel FRAMES times without reading any clock: run it under qemu\n"
      "with the icount plugin at FRAMES=N and 0; (difference)/N = instructions per frame.\n"
      "ISAs in this build:";
  for (const Isa& isa : kIsas) t += std::string(" ") + isa.name;
  t += std::string(" (active: ") + ig::activeIsa() + ")\n";
  t += "exit codes: 0 done; 1 a SIMD kernel's result differs from the scalar reference,\n"
       "  or interrupted (SIGINT, SIGTERM, SIGHUP); 2 bad command line (an option given\n"
       "  twice too)";
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  cuetrack::platform::installStopSignals();  // first: a stop at any moment ends as --help says
  int runs = 200, width = cuetrack::kMaxImageWidth, height = cuetrack::kMaxImageHeight;
  int icountFrames = -1;
  std::string isaName;
  char kernel = 0;  // 0 = all
  cli::Command cmd("cuetrack-microbench", "Times the integral-image kernels on one frame.",
                   exitCodes(), cli::Quotes::Value);
  cmd.number("--runs", "N", "timed runs per kernel and ISA, 1..10000 (default 200)", 1, kMaxRuns,
             &runs);
  cmd.option("--size", "WxH", "frame size (default and at most 640x480)",
             [&](const std::string& v) {
               return cli::imageSize(v, 1, cuetrack::kMaxImageWidth, cuetrack::kMaxImageHeight,
                                     &width, &height);
             });
  cmd.text("--isa", "NAME", "this ISA only (beside the scalar reference)", &isaName);
  cmd.option("--kernel", "rgb|depth|gray", "this kernel only", [&](const std::string& v) {
    int k = 0;
    const std::string why = cli::oneOf(v, "rgb|depth|gray", &k);
    kernel = "rdg"[k];
    return why;
  });
  cmd.number("--icount", "FRAMES", "run --kernel on --isa FRAMES times, 0..1000000, no clock", 0,
             1000000, &icountFrames);
  if (const int rc = cmd.parse(argc, argv); rc >= 0) return rc;
  const Isa* only = nullptr;
  if (!isaName.empty()) {
    for (const Isa& isa : kIsas)
      if (isaName == isa.name) only = &isa;
    if (!only) return cmd.fail("--isa '" + isaName + "': not in this build (see --help)");
    if (isaName == "avx2" && !ig::avx2Available())
      return cmd.fail("--isa avx2: this CPU has no AVX2");
  }
  fillFrame(width, height);

  if (icountFrames >= 0) {
    if (!only || !kernel) return cmd.fail("--icount needs --isa and --kernel");
    uint32_t check = 0;
    for (int f = 0; f < icountFrames; ++f) check ^= runKernel(*only, kernel, width, height);
    std::printf("icount %s %s %dx%d frames=%d checksum=%08x\n", only->name, kernelName(kernel),
                width, height, icountFrames, check);
    return 0;
  }

  const cuetrack::platform::MonotonicClock clock;
  std::printf("integral images, %dx%d, %d runs each, active ISA %s\n", width, height, runs,
              ig::activeIsa());
  std::printf("%-24s %-7s %11s %11s %9s %10s\n", "kernel", "isa", "median[us]", "min[us]", "Mpx/s",
              "vs scalar");
  for (const char k : {'r', 'd', 'g'}) {
    if (kernel && k != kernel) continue;
    double scalarMedianUs = 0;
    uint32_t scalarCheck = 0;
    for (const Isa& isa : kIsas) {
      if (only && &isa != only && std::strcmp(isa.name, "scalar") != 0) continue;
      if (!std::strcmp(isa.name, "avx2") && !ig::avx2Available()) continue;
      const uint32_t check = runKernel(isa, k, width, height);  // warm caches
      for (int r = 0; r < runs; ++r) {
        if (cuetrack::platform::stopRequested()) {
          std::fprintf(stderr, "cuetrack-microbench: interrupted (the figures above are whole)\n");
          return 1;
        }
        const uint64_t t0 = clock.nowUs();
        runKernel(isa, k, width, height);
        gTimesUs[r] = clock.nowUs() - t0;
      }
      std::sort(gTimesUs, gTimesUs + runs);
      const double medianUs =
          runs % 2 ? static_cast<double>(gTimesUs[runs / 2])
                   : 0.5 * static_cast<double>(gTimesUs[runs / 2 - 1] + gTimesUs[runs / 2]);
      if (!std::strcmp(isa.name, "scalar")) {
        scalarMedianUs = medianUs;
        scalarCheck = check;
      } else if (check != scalarCheck) {
        std::fprintf(stderr, "cuetrack-microbench: %s %s differs from scalar (%08x vs %08x)\n",
                     isa.name, kernelName(k), check, scalarCheck);
        return 1;
      }
      std::printf("%-24s %-7s %11.1f %11llu %9.1f %9.2fx\n", kernelName(k), isa.name, medianUs,
                  static_cast<unsigned long long>(gTimesUs[0]),
                  medianUs > 0 ? width * height / medianUs : 0.0,
                  medianUs > 0 ? scalarMedianUs / medianUs : 0.0);
    }
  }
  return 0;
}
