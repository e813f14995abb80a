// The synth:<scene>[:frames] source spec, as cuetrack, cuetrack-bench and cuetrack-convert
// take it: one line of error or a source of at least one frame. (pan: and still: specs
// open images through OpenCV, which the fuzz build has not; fuzz_recorded_specs fuzzes
// their parsing.)
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "cuetrack/drivers/OpenSource.hpp"

using namespace cuetrack;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 256) return 0;
  std::string spec = "synth:" + std::string(reinterpret_cast<const char*>(data), size);
  spec = spec.c_str();  // up to the first NUL, as a command line would give it
  SourceOptions opt;
  opt.maxFrames = 1;  // opening is what is fuzzed, not rendering
  char err[512] = "";
  std::unique_ptr<FrameSource> src = openFrameSource(spec.c_str(), opt, err, sizeof err);
  // One line of error; a newline in it can only be echoed from the spec (the reporter
  // prints those as '?').
  if (!src && (err[0] == '\0' || (std::strchr(err, '\n') && spec.find('\n') == std::string::npos)))
    __builtin_trap();
  if (src && src->frameCount() < 1) __builtin_trap();
  return 0;
}
