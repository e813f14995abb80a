#include "cuetrack/core/model/ScanOrder.hpp"

#include "cuetrack/core/base/FastMath.hpp"

namespace cuetrack {

const uint16_t* ScanOrder::sort(Span<const Box> boxes, int roiY0) {
  const int n = boxes.size();
  uint16_t start[kBands + 1] = {};
  for (int i = 0; i < n; ++i) {
    int band = (fmath::floorToInt(boxes[i].y) - roiY0) >> kBandShift;
    band = band < 0 ? 0 : (band >= kBands ? kBands - 1 : band);
    _band[i] = static_cast<uint8_t>(band);
    ++start[band + 1];
  }
  for (int b = 0; b < kBands; ++b) start[b + 1] = static_cast<uint16_t>(start[b + 1] + start[b]);
  for (int i = 0; i < n; ++i) _order[start[_band[i]]++] = static_cast<uint16_t>(i);
  return _order;
}

}  // namespace cuetrack
