// intrinsics.txt: accepted values have focal lengths in kMinFocalPx..kMaxFocalPx and a
// principal point in 0..kMaxImageWidth x 0..kMaxImageHeight.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  CameraIntrinsics k;
  char err[160];
  if (rec::parseIntrinsics(reinterpret_cast<const char*>(data), size, &k, err, sizeof err)) {
    if (!(k.fx >= rec::kMinFocalPx && k.fx <= rec::kMaxFocalPx) ||
        !(k.fy >= rec::kMinFocalPx && k.fy <= rec::kMaxFocalPx) ||
        !(k.cx >= 0.f && k.cx <= static_cast<float>(kMaxImageWidth)) ||
        !(k.cy >= 0.f && k.cy <= static_cast<float>(kMaxImageHeight)))
      __builtin_trap();
  }
  return 0;
}
