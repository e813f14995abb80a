// PGM/PPM header and pixel decoding on arbitrary bytes.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

namespace {
Rgb8 gRgb[kMaxPixels];
uint16_t gDepth[kMaxPixels];
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  char err[160];
  std::memset(err, 'X', sizeof err);  // a stale zero byte must not pass for a message
  rec::PnmHeader h;
  if (!rec::parsePnmHeader(data, size, &h, err, sizeof err)) {
    // A refusal always says why: a non-empty, terminated message.
    if (err[0] == '\0' || err[0] == 'X' || std::memchr(err, '\0', sizeof err) == nullptr)
      __builtin_trap();
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
