#include "cuetrack/core/model/IntegralChannels.hpp"

#include <cstring>

#include "cuetrack/core/kernels/Integral.hpp"

namespace cuetrack {

IntegralChannels::IntegralChannels() {
  std::memset(_gray, 0, sizeof(_gray));
  std::memset(_alpha2, 0, sizeof(_alpha2));
  std::memset(_beta, 0, sizeof(_beta));
  std::memset(_depth, 0, sizeof(_depth));
  std::memset(_count, 0, sizeof(_count));
}

void IntegralChannels::compute(const Frame& frame, const PixelRect& roi, bool useDepth) {
  const int w = roi.width(), h = roi.height();
  const int stride = w + 1;
  _t.gray = _gray;
  _t.alpha2 = _alpha2;
  _t.beta = _beta;
  _t.depth = _depth;
  _t.count = _count;
  _t.stride = stride;
  _t.width = w;
  _t.height = h;
  _t.originX = roi.x0;
  _t.originY = roi.y0;
  integral::rgb(frame.rgb.row(roi.y0) + roi.x0, frame.rgb.stride, w, h, _gray, _alpha2, _beta,
                stride);
  const bool depthOk = useDepth && frame.hasDepth() && frame.depthMm.width == frame.rgb.width &&
                       frame.depthMm.height == frame.rgb.height;
  if (depthOk) {
    integral::depth(frame.depthMm.row(roi.y0) + roi.x0, frame.depthMm.stride, w, h, _depth, _count,
                    stride);
  } else {
    const std::size_t bytes =
        static_cast<std::size_t>(stride) * static_cast<std::size_t>(h + 1) * sizeof(uint32_t);
    std::memset(_depth, 0, bytes);
    std::memset(_count, 0, bytes);
  }
}

namespace {
// r in table coordinates, clipped to the tables; false when nothing is left.
bool toTable(const PixelRect& r, const FrameTables& t, int* x0, int* y0, int* x1, int* y1) {
  *x0 = r.x0 - t.originX < 0 ? 0 : r.x0 - t.originX;
  *y0 = r.y0 - t.originY < 0 ? 0 : r.y0 - t.originY;
  *x1 = r.x1 - t.originX > t.width ? t.width : r.x1 - t.originX;
  *y1 = r.y1 - t.originY > t.height ? t.height : r.y1 - t.originY;
  return *x1 > *x0 && *y1 > *y0;
}
}  // namespace

float IntegralChannels::meanDepthMm(const PixelRect& r) const {
  int x0, y0, x1, y1;
  if (!toTable(r, _t, &x0, &y0, &x1, &y1)) return 0.f;
  const float n = detail::rect(_count, _t.stride, x0, y0, x1, y1);
  if (n < 0.5f) return 0.f;
  return detail::rect(_depth, _t.stride, x0, y0, x1, y1) / n;
}

float IntegralChannels::validDepthFraction(const PixelRect& r) const {
  int x0, y0, x1, y1;
  if (!toTable(r, _t, &x0, &y0, &x1, &y1)) return 0.f;  // also when r is empty
  return detail::rect(_count, _t.stride, x0, y0, x1, y1) /
         static_cast<float>(r.width() * r.height());
}

}  // namespace cuetrack
