// Portable float math: exp, log and atan2 written out in plain IEEE float operations,
// so every build (x86, aarch64, armhf; any libm) gives the same bits. sqrt comes from
// the hardware: IEEE 754 requires it correctly rounded, so it is already portable.
// Accuracy: fastLog ~1e-6 relative, fastExp ~2e-7 relative, fastAtan2 ~1e-5 rad.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace cuetrack::fmath {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kTwoPi = 6.28318530717959f;
inline constexpr float kLn2 = 0.693147180559945f;

inline uint32_t floatBits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
inline float bitsFloat(uint32_t b) {
  float v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

// Round half away from zero; for |v| < 2^31.
inline int roundToInt(float v) {
  return static_cast<int>(v >= 0.f ? v + 0.5f : v - 0.5f);
}
inline int floorToInt(float v) {
  const int i = static_cast<int>(v);
  return (static_cast<float>(i) > v) ? i - 1 : i;
}
inline float clampf(float v, float lo, float hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

inline float sqrtf(float v) {
  return std::sqrt(v);  // correctly rounded by IEEE 754 on every target
}

// Natural log for v > 0 (returns -88 for v <= 0 or denormals).
inline float fastLog(float v) {
  const uint32_t b = floatBits(v);
  if (!(v > 0.f) || (b >> 23) == 0) return -88.f;
  const int e = static_cast<int>(b >> 23) - 127;
  const float m = bitsFloat((b & 0x007FFFFFu) | 0x3F800000u);  // [1, 2)
  // ln m = 2 atanh(t), t = (m-1)/(m+1) in [0, 1/3)
  const float t = (m - 1.f) / (m + 1.f);
  const float t2 = t * t;
  const float s =
      t * (2.f + t2 * (0.666666667f + t2 * (0.4f + t2 * (0.285714286f + t2 * 0.222222222f))));
  return static_cast<float>(e) * kLn2 + s;
}

// e^v, clamped to [e^-87, e^87].
inline float fastExp(float v) {
  v = clampf(v, -87.f, 87.f);
  const int k = floorToInt(v * 1.44269504088896f + 0.5f);
  // Cody-Waite: ln 2 in two parts so r stays exact for large k.
  const float kf = static_cast<float>(k);
  const float r = (v - kf * 0.693145751953125f) - kf * 1.42860682030941723212e-6f;  // |r| <= ~0.35
  const float p =
      1.f +
      r * (1.f + r * (0.5f + r * (0.166666667f + r * (0.0416666667f +
                                                      r * (0.00833333333f + r * 0.00138888889f)))));
  return p * bitsFloat(static_cast<uint32_t>(k + 127) << 23);
}

// Angle of (x, y) in [0, 2 pi); 0 for the origin.
inline float fastAtan2(float y, float x) {
  const float ax = x < 0.f ? -x : x, ay = y < 0.f ? -y : y;
  const float mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
  if (mx == 0.f) return 0.f;
  const float a = mn / mx;
  const float s = a * a;
  // Minimax polynomial for atan on [0, 1], max error ~1e-5 rad.
  float r = ((((0.0208351f * s - 0.085133f) * s + 0.180141f) * s - 0.3302995f) * s + 0.999866f) * a;
  if (ay > ax) r = 1.57079632679f - r;
  if (x < 0.f) r = kPi - r;
  if (y < 0.f) r = kTwoPi - r;
  if (r >= kTwoPi) r = 0.f;
  return r;
}

}  // namespace cuetrack::fmath
