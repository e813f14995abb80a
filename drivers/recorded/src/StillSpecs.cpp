#include "cuetrack/drivers/StillSpecs.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

namespace cuetrack::rec {

namespace {

bool parseFloat(const std::string& s, float* out) {
  if (s.empty()) return false;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(v)) return false;
  *out = static_cast<float>(v);
  return true;
}

// The comma-separated fields of s.
std::vector<std::string> splitFields(const std::string& s) {
  std::vector<std::string> f;
  for (size_t start = 0;;) {
    const size_t comma = s.find(',', start);
    f.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return f;
    start = comma + 1;
  }
}

// f[first..] as numbers into out[0..], named by names[] in the error of the first that is
// not one.
bool parseNumbers(const std::vector<std::string>& f, size_t first, float* out,
                  const char* const* names, const char* spec, char* err, size_t errLen) {
  for (size_t i = first; i < f.size(); ++i) {
    if (!parseFloat(f[i], &out[i - first])) {
      std::snprintf(err, errLen, "%s: %s '%s' is not a number", spec, names[i - first],
                    f[i].c_str());
      return false;
    }
  }
  return true;
}

// The ":frames" suffix's count into *frames.
bool parseSpecFrames(const std::string& text, const char* spec, int* frames, char* err,
                     size_t errLen) {
  if (parseFrameCount(text.c_str(), frames)) return true;
  std::snprintf(err, errLen, "%s: frame count '%s' is not a number in 1..%ld", spec, text.c_str(),
                kMaxSpecFrames);
  return false;
}

// The two image paths must name something: an empty one would fail later as ": cannot
// decode image", naming nothing.
bool pathsGiven(const std::string& rgb, const std::string& depth, const char* spec, char* err,
                size_t errLen) {
  if (!rgb.empty() && !depth.empty()) return true;
  std::snprintf(err, errLen, "%s: the %s image's path is empty", spec,
                rgb.empty() ? "colour (RGB)" : "depth (DEPTH)");
  return false;
}

}  // namespace

bool parsePanSpec(const char* spec, PanSpec* out, char* err, size_t errLen) {
  std::string body = spec;
  if (body.rfind("pan:", 0) == 0) body = body.substr(4);
  PanSpec p;
  // Optional ":frames" after the last field.
  const size_t lastComma = body.find_last_of(',');
  const size_t colon = body.find(':', lastComma == std::string::npos ? 0 : lastComma);
  if (colon != std::string::npos) {
    if (!parseSpecFrames(body.substr(colon + 1), spec, &p.frames, err, errLen)) return false;
    body = body.substr(0, colon);
  }
  const std::vector<std::string> f = splitFields(body);
  if (f.size() != 10 && f.size() != 11) {
    std::snprintf(err, errLen,
                  "%s: expected pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames] "
                  "(%zu fields)",
                  spec, f.size());
    return false;
  }
  float v[9] = {0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 0.f, 1.f};
  static const char* const kField[9] = {"x", "y", "w", "h", "fx", "fy", "cx", "cy", "mmPerUnit"};
  if (!parseNumbers(f, 2, v, kField, spec, err, errLen)) return false;
  if (!(v[2] > 0.f) || !(v[3] > 0.f) || !(v[4] > 0.f) || !(v[5] > 0.f) || !(v[8] > 0.f)) {
    std::snprintf(err, errLen, "%s: w, h, fx, fy and mmPerUnit must be positive", spec);
    return false;
  }
  if (!pathsGiven(f[0], f[1], spec, err, errLen)) return false;
  p.rgbPath = f[0];
  p.depthPath = f[1];
  p.box = Box{v[0], v[1], v[2], v[3]};
  p.intrinsics = CameraIntrinsics{v[4], v[5], v[6], v[7]};
  p.mmPerUnit = v[8];
  *out = p;
  return true;
}

bool parseStillSpec(const char* spec, StillSpec* out, char* err, size_t errLen) {
  static const char kSyntax[] = "still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]";
  std::string body = spec;
  if (body.rfind("still:", 0) == 0) body = body.substr(6);
  StillSpec s;
  const size_t at = body.find_last_of('@');
  const size_t sceneColon = at == std::string::npos ? at : body.find_last_of(':', at);
  if (at == std::string::npos || sceneColon == std::string::npos) {
    std::snprintf(err, errLen, "%s: expected %s (no :SCENE@u,v,gapMm)", spec, kSyntax);
    return false;
  }
  s.scene = body.substr(sceneColon + 1, at - sceneColon - 1);
  std::string place = body.substr(at + 1);
  const size_t framesColon = place.find(':');
  if (framesColon != std::string::npos) {
    if (!parseSpecFrames(place.substr(framesColon + 1), spec, &s.frames, err, errLen)) return false;
    place = place.substr(0, framesColon);
  }
  const std::vector<std::string> f = splitFields(body.substr(0, sceneColon));
  const std::vector<std::string> p = splitFields(place);
  if ((f.size() != 6 && f.size() != 7) || p.size() != 3) {
    std::snprintf(err, errLen, "%s: expected %s (%zu still fields, %zu placement fields)", spec,
                  kSyntax, f.size(), p.size());
    return false;
  }
  float k[5] = {0.f, 0.f, 0.f, 0.f, 1.f};
  static const char* const kField[5] = {"fx", "fy", "cx", "cy", "mmPerUnit"};
  float uvGap[3] = {0.f, 0.f, 0.f};
  static const char* const kPlaceField[3] = {"u", "v", "gapMm"};
  if (!parseNumbers(f, 2, k, kField, spec, err, errLen) ||
      !parseNumbers(p, 0, uvGap, kPlaceField, spec, err, errLen))
    return false;
  if (!(k[0] > 0.f) || !(k[1] > 0.f) || !(k[4] > 0.f)) {
    std::snprintf(err, errLen, "%s: fx, fy and mmPerUnit must be positive", spec);
    return false;
  }
  if (!(uvGap[2] >= 0.f)) {
    std::snprintf(err, errLen, "%s: gapMm must be >= 0 (the target in front)", spec);
    return false;
  }
  if (s.scene.empty()) {
    std::snprintf(err, errLen, "%s: the scene's name (SCENE before '@') is empty", spec);
    return false;
  }
  if (!pathsGiven(f[0], f[1], spec, err, errLen)) return false;
  s.rgbPath = f[0];
  s.depthPath = f[1];
  s.intrinsics = CameraIntrinsics{k[0], k[1], k[2], k[3]};
  s.mmPerUnit = k[4];
  s.uPx = uvGap[0];
  s.vPx = uvGap[1];
  s.gapMm = uvGap[2];
  *out = s;
  return true;
}

std::string stillLabel(const std::string& rgbPath) {
  const auto lastPart = [](const std::string& p) {
    const size_t k = p.find_last_of('/');
    return k == std::string::npos ? p : p.substr(k + 1);
  };
  const size_t slash = rgbPath.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : rgbPath.substr(0, slash);
  std::string folder = lastPart(dir);
  if ((folder == "color" || folder == "rgb") && dir.find('/') != std::string::npos)
    folder = lastPart(dir.substr(0, dir.find_last_of('/')));
  return (folder.empty() ? std::string() : folder + "-") + fileStem(rgbPath);
}

bool parseRandomSpec(const char* spec, RandomSpec* out, char* err, size_t errLen) {
  static const char kSyntax[] = "rand:SEED[:DATA]";
  std::string body = spec ? spec : "";
  if (body.rfind("rand:", 0) == 0) body = body.substr(5);
  const size_t colon = body.find(':');
  const std::string seed = body.substr(0, colon);
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(seed.c_str(), &end, 10);
  if (seed.empty() || seed.find_first_not_of("0123456789") != std::string::npos || errno != 0 ||
      *end != '\0') {
    std::snprintf(err, errLen, "%s: the seed '%s' is not a whole number (expected %s)", spec,
                  seed.c_str(), kSyntax);
    return false;
  }
  out->seed = v;
  out->dataDir = colon == std::string::npos ? std::string() : body.substr(colon + 1);
  if (colon != std::string::npos && out->dataDir.empty()) {
    std::snprintf(err, errLen, "%s: the data folder after the seed is empty (expected %s)", spec,
                  kSyntax);
    return false;
  }
  return true;
}

}  // namespace cuetrack::rec
