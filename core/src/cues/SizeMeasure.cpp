#include "cuetrack/core/cues/SizeMeasure.hpp"

#include <cstdint>

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

namespace {
constexpr float kBandFrom = 0.25f;  // profile samples from the box's middle half
constexpr float kBandTo = 0.75f;
constexpr int kMaxSamples = 16;  // band rows (columns) read per column (row)
constexpr int kMaxCells = kMaxImageWidth > kMaxImageHeight ? kMaxImageWidth : kMaxImageHeight;

struct Span {
  int lo = 0, hi = 0;  // [lo, hi)
};

// [lo, hi) of floor(from)..floor(to) clipped to [0, n).
Span clipSpan(float from, float to, int n) {
  Span s{fmath::floorToInt(from), fmath::floorToInt(to)};
  if (s.lo < 0) s.lo = 0;
  if (s.hi > n) s.hi = n;
  if (s.hi < s.lo) s.hi = s.lo;
  return s;
}

// Sample i of m spread evenly over the band (cell centres).
int sampleAt(const Span& band, int i, int m) {
  return band.lo + ((2 * i + 1) * (band.hi - band.lo)) / (2 * m);
}

// A cell (column or row) belongs to the target when most of its valid samples, and at
// least a quarter of all its samples, lie in the slab (holes neither add nor veto).
bool occupied(int in, int valid, int samples) {
  return 2 * in > valid && 4 * in >= samples;
}

// Length of the run of occupied cells through `centre` (or the nearest occupied cell
// within `search`), bridging up to maxGap free cells; 0 when there is none or the run
// reaches either end of [0, n) (it may go on beyond the window).
int centralRun(const uint8_t* occ, int n, int centre, int search, int maxGap, int* firstOut) {
  int start = -1;
  for (int d = 0; d <= search && start < 0; ++d) {
    if (centre - d >= 0 && occ[centre - d] != 0)
      start = centre - d;
    else if (centre + d < n && occ[centre + d] != 0)
      start = centre + d;
  }
  if (start < 0) return 0;
  int last = start, gap = 0, i = start + 1;
  for (; i < n; ++i) {
    if (occ[i] != 0) {
      last = i;
      gap = 0;
    } else if (++gap > maxGap) {
      break;
    }
  }
  if (i == n) return 0;
  int first = start;
  gap = 0;
  for (i = start - 1; i >= 0; --i) {
    if (occ[i] != 0) {
      first = i;
      gap = 0;
    } else if (++gap > maxGap) {
      break;
    }
  }
  if (i < 0) return 0;
  *firstOut = first;
  return last - first + 1;
}

int maxGapFor(float sidePx) {
  return 2 + fmath::floorToInt(sidePx * (1.f / 32.f));
}

// The central run of occ[0..n) around `centre` for a box side of sidePx, as a length and
// a midpoint in image px (the window starts at `origin`); false when there is none.
bool centralExtent(const uint8_t* occ, int n, int centre, float sidePx, int origin, float* lengthPx,
                   float* midPx) {
  int first = 0;
  const int run =
      centralRun(occ, n, centre, 2 + fmath::floorToInt(0.125f * sidePx), maxGapFor(sidePx), &first);
  *lengthPx = static_cast<float>(run);
  *midPx = static_cast<float>(origin + first) + 0.5f * static_cast<float>(run);
  return run > 0;
}
}  // namespace

SilhouetteExtent measureSilhouette(const DepthView& depth, const Box& box, float nearMm,
                                   float farMm, float grow, SilhouetteAxes axes) {
  SilhouetteExtent out;
  if (depth.empty() || box.empty()) return out;
  const int nearI = nearMm < 1.f ? 1 : fmath::floorToInt(nearMm) + 1;
  const float farC =
      farMm > static_cast<float>(kMaxDepthMm) ? static_cast<float>(kMaxDepthMm) : farMm;
  const int farI = fmath::floorToInt(farC);
  if (farI < nearI) return out;
  const uint16_t lo = static_cast<uint16_t>(nearI), span = static_cast<uint16_t>(farI - nearI);
  const Span wx = clipSpan(box.x - grow * box.w, box.x + (1.f + grow) * box.w, depth.width);
  const Span wy = clipSpan(box.y - grow * box.h, box.y + (1.f + grow) * box.h, depth.height);
  const int nx = wx.hi - wx.lo, ny = wy.hi - wy.lo;
  if (nx < 3 || ny < 3) return out;
  const int cx = fmath::floorToInt(box.x + 0.5f * box.w) - wx.lo;
  const int cy = fmath::floorToInt(box.y + 0.5f * box.h) - wy.lo;
  if (cx < 0 || cx >= nx || cy < 0 || cy >= ny) return out;

  uint8_t in[kMaxCells], valid[kMaxCells], occ[kMaxCells];
  // Width: columns of the window, sampled on the box's middle rows.
  const Span by = clipSpan(box.y + kBandFrom * box.h, box.y + kBandTo * box.h, depth.height);
  if (by.hi > by.lo) {
    const int m = by.hi - by.lo < kMaxSamples ? by.hi - by.lo : kMaxSamples;
    for (int i = 0; i < nx; ++i) in[i] = valid[i] = 0;
    for (int s = 0; s < m; ++s) {
      const uint16_t* row = depth.row(sampleAt(by, s, m)) + wx.lo;
      // Unsigned range tests (one compare each; the loop vectorises).
      for (int i = 0; i < nx; ++i) {
        valid[i] =
            static_cast<uint8_t>(valid[i] + (static_cast<uint16_t>(row[i] - 1u) < kMaxDepthMm));
        in[i] = static_cast<uint8_t>(in[i] + (static_cast<uint16_t>(row[i] - lo) <= span));
      }
    }
    for (int i = 0; i < nx; ++i) occ[i] = occupied(in[i], valid[i], m) ? 1 : 0;
    out.hasWidth = centralExtent(occ, nx, cx, box.w, wx.lo, &out.widthPx, &out.centreXPx);
  }
  // Height: rows of the window, sampled on the box's middle columns.
  const Span bx = clipSpan(box.x + kBandFrom * box.w, box.x + kBandTo * box.w, depth.width);
  if (axes == SilhouetteAxes::Both && bx.hi > bx.lo) {
    const int m = bx.hi - bx.lo < kMaxSamples ? bx.hi - bx.lo : kMaxSamples;
    int cols[kMaxSamples];
    for (int s = 0; s < m; ++s) cols[s] = sampleAt(bx, s, m);
    for (int j = 0; j < ny; ++j) {
      const uint16_t* row = depth.row(wy.lo + j);
      int nIn = 0, nValid = 0;
      for (int s = 0; s < m; ++s) {
        const uint16_t d = row[cols[s]];
        nValid += static_cast<uint16_t>(d - 1u) < kMaxDepthMm;
        nIn += static_cast<uint16_t>(d - lo) <= span;
      }
      occ[j] = occupied(nIn, nValid, m) ? 1 : 0;
    }
    out.hasHeight = centralExtent(occ, ny, cy, box.h, wy.lo, &out.heightPx, &out.centreYPx);
  }
  return out;
}

float cylinderDiameterMm(float wPx, float surfaceMm, const CameraIntrinsics& k) {
  return wPx * surfaceMm / (k.fx - 0.5f * wPx);
}

float cylinderHeightMm(float hPx, float surfaceMm, float diameterMm, const CameraIntrinsics& k) {
  return hPx * (surfaceMm + 0.5f * diameterMm) / k.fy;
}

}  // namespace cuetrack
