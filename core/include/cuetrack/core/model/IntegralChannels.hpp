// The frame's integral tables (gray, 2 alpha, beta, depth, valid count), computed
// only over a region of interest: the part of the frame that particles and
// negative examples can touch this step. Fixed storage sized for a full frame.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"  // PixelRect, clipBox
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/model/Features.hpp"

namespace cuetrack {

class IntegralChannels {
 public:
  // Writes every table once: the first frame that needs the whole image (the first one
  // lost) would otherwise pay for faulting in 6 MB of fresh pages (14 ms on x86).
  IntegralChannels();
  // Depth tables are all zero (no valid pixel) when the frame has no depth or useDepth is off.
  void compute(const Frame& frame, const PixelRect& roi, bool useDepth);
  const FrameTables& tables() const { return _t; }
  // Mean valid depth in frame rectangle r [mm]; 0 when it has no valid pixel.
  float meanDepthMm(const PixelRect& r) const;
  // The fraction of frame rectangle r's pixels with valid depth; 0 when r is empty or
  // outside the tabulated region.
  float validDepthFraction(const PixelRect& r) const;

 private:
  uint32_t _gray[kMaxIntegralCells];
  int32_t _alpha2[kMaxIntegralCells];
  int32_t _beta[kMaxIntegralCells];
  uint32_t _depth[kMaxIntegralCells];
  uint32_t _count[kMaxIntegralCells];
  FrameTables _t{};
};
// 5 tables x 308,321 cells x 4 B = 6,166,420 B (the largest part of the tracker).
static_assert(sizeof(IntegralChannels) <= 5u * kMaxIntegralCells * 4u + 128u,
              "integral tables: 5 x (641 x 481) x 4 B");

}  // namespace cuetrack
