// PGM/PPM header and pixel decoding on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "cuetrack/core/Config.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

namespace {
Rgb8 gRgb[kMaxPixels];
uint16_t gDepth[kMaxPixels];
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  char err[160];
  rec::PnmHeader h;
  if (!rec::parsePnmHeader(data, size, &h, err, sizeof err)) {
    if (std::memchr(err, '\0', sizeof err) == nullptr) __builtin_trap();  // always terminated
    return 0;
  }
  if (h.width < 1 || h.height < 1 || h.width > kMaxImageWidth || h.height > kMaxImageHeight)
    __builtin_trap();  // the header parser must enforce the capacity
  if (h.dataOffset + h.dataBytes() > size) __builtin_trap();
  rec::decodePnmRgb(data, size, h, gRgb, err, sizeof err);
  rec::decodePnm16(data, size, h, rec::Endian::Little, gDepth, err, sizeof err);
  rec::decodePnm16(data, size, h, rec::Endian::Big, gDepth, err, sizeof err);
  return 0;
}
