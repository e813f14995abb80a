// fakenect INDEX.txt: every line through the entry parser.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* text = reinterpret_cast<const char*>(data);
  size_t pos = 0;
  const char* line = nullptr;
  size_t len = 0;
  char err[200];
  while (rec::nextLine(text, size, &pos, &line, &len)) {
    if (line < text || line + len > text + size) __builtin_trap();
    rec::IndexEntry e;
    if (rec::parseIndexLine(line, len, &e, err, sizeof err)) {
      if (!(e.kind == 'r' || e.kind == 'd' || e.kind == 'a')) __builtin_trap();
      if (!std::isfinite(e.seconds) || e.seconds < 0.0) __builtin_trap();
    }
  }
  return 0;
}
