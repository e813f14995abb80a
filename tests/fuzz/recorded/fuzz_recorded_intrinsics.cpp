// intrinsics.txt: accepted values are finite with positive focal lengths.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  CameraIntrinsics k;
  char err[160];
  if (rec::parseIntrinsics(reinterpret_cast<const char*>(data), size, &k, err, sizeof err)) {
    if (!(k.fx > 0.f) || !(k.fy > 0.f) || !std::isfinite(k.cx) || !std::isfinite(k.cy))
      __builtin_trap();
  }
  return 0;
}
