// FNV-1a over a frame's colour and depth: the golden frames of the synthetic scenes
// (test_drivers_synth, test_drivers_scene_draw), the same on x86, aarch64 and armhf.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::test {

inline uint64_t frameHash(const FrameSlot& f) {
  uint64_t h = 1469598103934665603ull;
  auto add = [&h](const void* p, size_t n) {
    const uint8_t* b = static_cast<const uint8_t*>(p);
    for (size_t i = 0; i < n; ++i) {
      h ^= b[i];
      h *= 1099511628211ull;
    }
  };
  const size_t n = static_cast<size_t>(f.rgb.width()) * static_cast<size_t>(f.rgb.height());
  add(f.rgb.data(), n * 3);
  add(f.depthMm.data(), n * 2);
  return h;
}

}  // namespace cuetrack::test
