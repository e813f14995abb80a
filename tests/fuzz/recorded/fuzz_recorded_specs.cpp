// The pan: and still: source specs (rec::parsePanSpec, rec::parseStillSpec), as cuetrack,
// cuetrack-bench and cuetrack-convert take them: one line of error naming the spec, or
// values the readers can use as they are (positive sizes and focal lengths, a frame
// count in range, a scene name and both paths).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "cuetrack/drivers/RecordedParsers.hpp"
#include "cuetrack/drivers/StillSpecs.hpp"

using namespace cuetrack;

namespace {

// An error is one line (a newline in it can only be echoed from the spec) and names the spec.
void checkError(const std::string& spec, const char* err) {
  if (err[0] == '\0') __builtin_trap();
  if (std::strchr(err, '\n') && spec.find('\n') == std::string::npos) __builtin_trap();
  if (std::strncmp(err, spec.c_str(), spec.size() < 16 ? spec.size() : 16) != 0) __builtin_trap();
}

bool framesOk(int frames) {
  return frames >= 1 && frames <= rec::kMaxSpecFrames;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 512) return 0;
  std::string body(reinterpret_cast<const char*>(data), size);
  body = body.c_str();  // up to the first NUL, as a command line would give it
  char err[1024] = "";

  const std::string pan = "pan:" + body;
  rec::PanSpec p;
  if (rec::parsePanSpec(pan.c_str(), &p, err, sizeof err)) {
    if (p.rgbPath.empty() || p.depthPath.empty() || !(p.box.w > 0.f) || !(p.box.h > 0.f) ||
        !(p.intrinsics.fx > 0.f) || !(p.intrinsics.fy > 0.f) || !(p.mmPerUnit > 0.f) ||
        !framesOk(p.frames))
      __builtin_trap();
  } else {
    checkError(pan, err);
  }

  err[0] = '\0';
  const std::string still = "still:" + body;
  rec::StillSpec s;
  if (rec::parseStillSpec(still.c_str(), &s, err, sizeof err)) {
    if (s.rgbPath.empty() || s.depthPath.empty() || s.scene.empty() || !(s.intrinsics.fx > 0.f) ||
        !(s.intrinsics.fy > 0.f) || !(s.mmPerUnit > 0.f) || !(s.gapMm >= 0.f) ||
        (s.frames != -1 && !framesOk(s.frames)))
      __builtin_trap();
  } else {
    checkError(still, err);
  }
  rec::stillLabel(body);
  return 0;
}
