#include "BoxFit.hpp"

namespace cuetrack::app {

bool looksLikeCorners(const Box& box, int width, int height, Box* asXywh) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const bool cornersOrdered = box.x >= 0.f && box.y >= 0.f && box.w > box.x && box.h > box.y;
  const bool runsPast = box.x + box.w > w || box.y + box.h > h;
  const bool fitsAsCorners = box.w <= w && box.h <= h;
  if (!(cornersOrdered && runsPast && fitsAsCorners)) return false;
  *asXywh = Box{box.x, box.y, box.w - box.x, box.h - box.y};
  return true;
}

}  // namespace cuetrack::app
