// Stills read whole through OpenCV (host only, cuetrack_recorded_cv): 16-bit PNG depth
// (scaled to mm by the caller's unit, e.g. TUM's value / 5 = mm) and any colour image OpenCV
// reads. Sizes up to kMaxImageWidth x kMaxImageHeight; false with "path: reason" in err.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

// mmPerUnit: the file's depth unit in mm (TUM's 0.2), applied rounded and saturated.
bool loadDepthPng16(const char* path, FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>& out,
                    char* err, size_t errLen, float mmPerUnit = 1.f);
bool loadColourImage(const char* path, FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight>& out,
                     char* err, size_t errLen);

}  // namespace cuetrack
