#include "cuetrack/core/cues/DepthMedian.hpp"

namespace cuetrack {

bool DepthMedian::of(const DepthView& depthMm, const Box& box, float* outMm) {
  const PixelRect r = clipBox(box, depthMm.width, depthMm.height);
  constexpr int kBins = kMaxDepthMm / kBinMm + 1;
  for (int i = 0; i < kBins; ++i) _histogram[i] = 0;
  uint32_t n = 0;
  for (int y = r.y0; y < r.y1; ++y) {
    const uint16_t* row = depthMm.row(y);
    for (int x = r.x0; x < r.x1; ++x) {
      const uint16_t d = row[x];
      if (d == 0 || d > kMaxDepthMm) continue;
      ++_histogram[d / kBinMm];
      ++n;
    }
  }
  if (n == 0) return false;
  uint32_t acc = 0;
  for (int i = 0; i < kBins; ++i) {
    acc += _histogram[i];
    if (2 * acc >= n) {
      *outMm = static_cast<float>(i * kBinMm) + 0.5f * kBinMm;
      return true;
    }
  }
  return false;
}

}  // namespace cuetrack
