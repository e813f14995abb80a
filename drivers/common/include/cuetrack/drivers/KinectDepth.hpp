// Kinect v1 raw 11-bit disparity <-> depth in millimetres.
//
// Model (one formula for the whole project, see docs/recordings.md):
//   depth [m] = 1 / (raw * -0.0030711016 + 3.3309495161)
// the least-squares fit of Stéphane Magnenat published on the OpenKinect wiki
// ("Imaging Information") and used by ROS and many Kinect v1 tools. raw counts
// disparity in 1/8 px steps; 2047 means "no measurement". raw 0 is 300 mm; the
// formula diverges at raw ~1084.6, and kMaxDepthMm (10 m) is raw 1052.
// Header-only, no allocation: the board's driver and the synthetic scenes share it.
#pragma once

#include <cmath>
#include <cstdint>

#include "cuetrack/core/config/Config.hpp"

namespace cuetrack::kinect {

inline constexpr uint16_t kRawNoDepth = 2047;  // libfreenect's "no reading" value
inline constexpr double kRawToInvMetresA = -0.0030711016;
inline constexpr double kRawToInvMetresB = 3.3309495161;

// Depth [mm] for a raw disparity (rounded to the nearest mm); 0 when the value means
// no reading or maps outside (0, kMaxDepthMm].
inline uint16_t rawToMm(uint16_t raw) {
  if (raw >= kRawNoDepth) return 0;
  const double inv = static_cast<double>(raw) * kRawToInvMetresA + kRawToInvMetresB;  // [1/m]
  if (inv <= 0.0) return 0;
  const double mm = 1000.0 / inv;
  if (mm > static_cast<double>(kMaxDepthMm)) return 0;
  return static_cast<uint16_t>(mm + 0.5);
}

// Continuous raw disparity for a depth [mm] (the inverse of the formula, unrounded).
inline double mmToRawExact(double depthMm) {
  return (1000.0 / depthMm - kRawToInvMetresB) / kRawToInvMetresA;
}

// Raw disparity for a depth [mm]: the raw value whose depth is nearest; kRawNoDepth for 0
// or out-of-range depth. rawToMm(mmToRaw(d)) == d whenever d came from rawToMm.
inline uint16_t mmToRaw(uint16_t depthMm) {
  if (depthMm == 0 || depthMm > kMaxDepthMm) return kRawNoDepth;
  const double r = mmToRawExact(depthMm);
  if (r < -1.0) return kRawNoDepth;  // well nearer than raw 0 (300 mm): the sensor cannot see it
  long best = static_cast<long>(std::floor(r));
  // Pick the neighbour whose rounded depth is nearest (the mapping is non-linear).
  const long cands[2] = {best, best + 1};
  int bestErr = 1 << 30;
  long pick = best;
  for (long c : cands) {
    if (c < 0 || c >= kRawNoDepth) continue;
    const int mm = rawToMm(static_cast<uint16_t>(c));
    if (mm == 0) continue;
    const int err = mm > depthMm ? mm - depthMm : depthMm - mm;
    if (err < bestErr) {
      bestErr = err;
      pick = c;
    }
  }
  if (bestErr == (1 << 30)) return kRawNoDepth;
  return static_cast<uint16_t>(pick);
}

// Precomputed raw -> mm table: 4 KiB, filled once, then one load per pixel.
struct RawToMmTable {
  uint16_t mm[2048];
  RawToMmTable() {
    for (int r = 0; r < 2048; ++r) mm[r] = rawToMm(static_cast<uint16_t>(r));
  }
  uint16_t operator()(uint16_t raw) const { return raw < 2048 ? mm[raw] : 0; }
};

}  // namespace cuetrack::kinect
