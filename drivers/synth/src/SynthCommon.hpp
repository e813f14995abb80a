// What the synthetic source's files share (SyntheticSource.cpp, SceneRaster.cpp,
// KinectDepthModel.cpp): constants, the seeded mixer and a floor without libm. Private
// to drivers/synth.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/drivers/SceneSpec.hpp"

namespace cuetrack::synth {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr uint8_t kBackgroundOwner = 255;  // the owner of a wall, floor or still pixel
inline constexpr float kHoleZMm = 1e9f;  // a still's pixel without a reading: nothing is behind it

inline uint64_t splitmix64(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// floor() without the libm call that baseline x86-64 makes of std::floor.
inline int floorToInt(float v) {
  const int i = static_cast<int>(v);
  return i - (static_cast<float>(i) > v);
}

// Where a motion puts its object at time tS [s] (MotionSpec's formula; SyntheticSource.cpp).
void motionPosition(const MotionSpec& m, float tS, float outMm[3]);

// A kTextureSize x kTextureSize tile of t's pattern (SceneRaster.cpp).
void makeTexture(const TextureSpec& t, Rgb8* tex);

}  // namespace cuetrack::synth
