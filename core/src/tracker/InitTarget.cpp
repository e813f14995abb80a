#include "cuetrack/core/tracker/InitTarget.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

InitError initTarget(const RgbView& rgb, const Box& box, Box* target) {
  if (rgb.empty()) return InitError::NoColour;
  if (rgb.width > kMaxImageWidth || rgb.height > kMaxImageHeight) return InitError::ImageTooLarge;
  if (box.empty()) return InitError::EmptyBox;
  const int imageW = rgb.width, imageH = rgb.height;
  // Intersect the box with the image.
  const float x0 = fmath::clampf(box.x, 0.f, static_cast<float>(imageW));
  const float y0 = fmath::clampf(box.y, 0.f, static_cast<float>(imageH));
  const float x1 = fmath::clampf(box.x + box.w, 0.f, static_cast<float>(imageW));
  const float y1 = fmath::clampf(box.y + box.h, 0.f, static_cast<float>(imageH));
  if (!(x1 > x0) || !(y1 > y0)) return InitError::BoxOutsideImage;
  *target = Box{x0, y0, x1 - x0, y1 - y0};
  if (target->w < kMinTargetPx || target->h < kMinTargetPx) return InitError::BoxTooSmall;
  return InitError::None;
}

}  // namespace cuetrack
