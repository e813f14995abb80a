// Ground-truth files in both formats; every accepted box converts to pixels.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/GroundTruth.hpp"

using namespace cuetrack;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  char err[256];
  for (GtFormat f : {GtFormat::Bobot, GtFormat::Otb}) {
    GroundTruth gt;
    if (!gt.parse(text, size, "fuzz.txt", f, err, sizeof err)) continue;
    for (int i = 0; i < gt.count(); ++i) {
      Box b;
      if (!gt.boxAt(i, 640, 480, &b)) __builtin_trap();
      if (!std::isfinite(b.x) || !std::isfinite(b.y) || !std::isfinite(b.w) || !std::isfinite(b.h))
        __builtin_trap();
    }
  }
  return 0;
}
