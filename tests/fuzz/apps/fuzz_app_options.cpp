// cuetrack's command line: the input is argv, NUL-separated. Whatever it holds, the
// parser returns one of its three results, and a run it accepts is a sane one.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "Options.hpp"

using namespace cuetrack::app;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static char text[4096];
  if (size >= sizeof text) return 0;
  std::memcpy(text, data, size);
  text[size] = '\0';
  char* argv[65];
  int argc = 0;
  argv[argc++] = const_cast<char*>("cuetrack");
  for (size_t start = 0; start <= size && argc < 64;) {
    argv[argc++] = text + start;
    start += std::strlen(text + start) + 1;
  }
  argv[argc] = nullptr;
  AppOptions o;
  char err[512];
  err[0] = '\0';
  const ParseResult r = parseOptions(argc, argv, &o, err, sizeof err);
  // An error is a line; a newline in it can only be one echoed from an argument (the
  // reporter prints those as '?').
  if (r == ParseResult::Error &&
      (err[0] == '\0' || (std::strchr(err, '\n') && !std::memchr(data, '\n', size))))
    __builtin_trap();
  if (r == ParseResult::Run) {
    if (o.frames == 0 || o.frames < -1) __builtin_trap();  // 0 is refused
    if (o.hasBox && !(o.box.w > 0.f && o.box.h > 0.f && std::isfinite(o.box.x))) __builtin_trap();
    if (o.mavSysId < 1 || o.mavSysId > 255 || o.mavCompId < 1 || o.mavCompId > 255)
      __builtin_trap();
  }
  return 0;
}
