// The track as the window and the video draw it: what the tracker left on a frame.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

struct ViewTrack {
  uint32_t frameIndex = 0;
  uint8_t state = 0;  // CTP_STATE_*
  uint8_t flags = 0;  // CTP_FLAG_* (occluded is drawn as such)
  Box box{};          // [px]
  float confidence = 0.f;
};

}  // namespace cuetrack::app
