#include "TargetCheck.hpp"

#include <cmath>
#include <cstdio>

namespace cuetrack::app {
namespace {

constexpr int kBinsPerChannel = 4;  // coarse: noise and shading must not make a wall "differ"
constexpr int kBins = kBinsPerChannel * kBinsPerChannel * kBinsPerChannel;

int grey(const Rgb8& p) {
  return (p.r + 2 * p.g + p.b) >> 2;
}

int bin(const Rgb8& p) {
  constexpr int s = 8 - 2;  // 256 / 4 = 64 per bin
  return ((p.r >> s) * kBinsPerChannel + (p.g >> s)) * kBinsPerChannel + (p.b >> s);
}

constexpr int kDepthBinMm = 32;
constexpr int kDepthBins = 256;  // 0..8 m: beyond any RGB-D camera we read

struct DepthHistogram {
  uint32_t count[kDepthBins] = {};
  uint32_t n = 0;
  void add(uint16_t mm) {
    if (mm == 0) return;  // no measurement
    const int b = mm / kDepthBinMm;
    ++count[b < kDepthBins ? b : kDepthBins - 1];
    ++n;
  }
  float medianMm() const {
    uint32_t seen = 0;
    for (int b = 0; b < kDepthBins; ++b) {
      seen += count[b];
      if (2 * seen >= n) return (static_cast<float>(b) + 0.5f) * kDepthBinMm;
    }
    return 0.f;
  }
};

struct Rect {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1), inside the image
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
};

Rect clip(float x, float y, float w, float h, int width, int height) {
  auto c = [](float v, int hi) {
    const int i = static_cast<int>(std::lround(v));
    return i < 0 ? 0 : (i > hi ? hi : i);
  };
  return Rect{c(x, width), c(y, height), c(x + w, width), c(y + h, height)};
}

}  // namespace

TargetCheck checkTarget(const Frame& frame, const Box& box) {
  TargetCheck out;
  const RgbView& rgb = frame.rgb;
  if (rgb.empty()) return out;
  const Rect in = clip(box.x, box.y, box.w, box.h, rgb.width, rgb.height);
  if (in.empty()) return out;  // the tracker refuses it with its own reason

  constexpr float kBorderPx = 1.f;
  if (box.x < kBorderPx || box.y < kBorderPx || box.x + box.w > rgb.width - kBorderPx ||
      box.y + box.h > rgb.height - kBorderPx) {
    out.issues |= kTargetTouchesBorder;
  }

  // Texture: the tracker's colour and shape cues both need some structure inside.
  double gradSum = 0.0;
  long gradN = 0;
  for (int y = in.y0; y + 1 < in.y1; ++y) {
    for (int x = in.x0; x + 1 < in.x1; ++x) {
      const int g = grey(rgb.at(x, y));
      gradSum += std::abs(grey(rgb.at(x + 1, y)) - g) + std::abs(grey(rgb.at(x, y + 1)) - g);
      ++gradN;
    }
  }
  out.gradientPerPx = gradN > 0 ? static_cast<float>(gradSum / static_cast<double>(gradN)) : 0.f;

  // Colour against a ring of half the box's size around it: a box on a wall looks like
  // the wall, and the colour model then matches the wall everywhere.
  const Rect ring = clip(box.x - box.w * 0.5f, box.y - box.h * 0.5f, box.w * 2.f, box.h * 2.f,
                         rgb.width, rgb.height);
  uint32_t hin[kBins] = {}, hring[kBins] = {};
  uint32_t nin = 0, nring = 0;
  DepthHistogram din, dring;
  const bool depth =
      frame.hasDepth() && frame.depthMm.width == rgb.width && frame.depthMm.height == rgb.height;
  for (int y = ring.y0; y < ring.y1; ++y) {
    for (int x = ring.x0; x < ring.x1; ++x) {
      const int b = bin(rgb.at(x, y));
      if (in.contains(x, y)) {
        ++hin[b];
        ++nin;
        if (depth) din.add(frame.depthMm.at(x, y));
      } else {
        ++hring[b];
        ++nring;
        if (depth) dring.add(frame.depthMm.at(x, y));
      }
    }
  }
  if (nin > 0 && nring > 0) {
    double bc = 0.0;
    for (int b = 0; b < kBins; ++b) {
      bc += std::sqrt(static_cast<double>(hin[b]) / nin * static_cast<double>(hring[b]) / nring);
    }
    out.surroundSimilarity = static_cast<float>(bc);
  }
  bool standsOutInDepth = false;
  if (din.n > 0 && dring.n > 0) {
    const float d = din.medianMm() - dring.medianMm();
    out.depthContrastMm = d < 0.f ? -d : d;
    standsOutInDepth = out.depthContrastMm >= kMinDepthContrastMm;
  }
  if (!standsOutInDepth) {
    if (out.gradientPerPx < kMinGradientPerPx) out.issues |= kTargetLowTexture;
    if (out.surroundSimilarity > kMaxSurroundSimilarity &&
        out.gradientPerPx < kMaxGradientLikeSurroundings)
      out.issues |= kTargetLikeSurroundings;
  }

  if (depth) {
    long missing = 0, n = 0;
    for (int y = in.y0; y < in.y1; ++y) {
      for (int x = in.x0; x < in.x1; ++x) {
        missing += frame.depthMm.at(x, y) == 0;
        ++n;
      }
    }
    out.missingDepthFraction = static_cast<float>(missing) / static_cast<float>(n);
    if (out.missingDepthFraction > kMaxMissingDepthFraction) out.issues |= kTargetMissingDepth;
  }
  return out;
}

void describeTargetIssues(const TargetCheck& c, char* out, size_t outLen) {
  if (outLen == 0) return;
  out[0] = '\0';
  size_t used = 0;
  auto add = [&](const char* fmt, double v) {
    if (used >= outLen) return;
    const int n = std::snprintf(out + used, outLen - used, fmt, used ? "; " : "", v);
    if (n > 0) used += static_cast<size_t>(n);
  };
  if (c.issues & kTargetLowTexture)
    add("%salmost no texture (mean gradient %.1f/px)", c.gradientPerPx);
  if (c.issues & kTargetLikeSurroundings)
    add("%slooks like its surroundings, e.g. a plain wall (colour similarity %.2f)",
        c.surroundSimilarity);
  if (c.issues & kTargetMissingDepth)
    add("%sdepth mostly missing (%.0f%% of its pixels)", c.missingDepthFraction * 100.0);
  if ((c.issues & kTargetTouchesBorder) && used < outLen)
    std::snprintf(out + used, outLen - used, "%stouches the image border", used ? "; " : "");
}

}  // namespace cuetrack::app
