#include "cuetrack/drivers/StillScene.hpp"

#include <cmath>
#include <cstdio>

#include "cuetrack/drivers/ImageLoaders.hpp"
#include "cuetrack/drivers/StillPlacement.hpp"
#include "cuetrack/drivers/StillSpecs.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

struct StillSceneReader::Still {
  FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight> rgb;
  FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight> depthMm;
};

StillSceneReader::StillSceneReader() : _still(new Still) {}
StillSceneReader::~StillSceneReader() = default;

bool StillSceneReader::open(const char* spec, const SourceOptions& opt) {
  _error[0] = '\0';
  _scene.reset();
  rec::StillSpec p;
  if (!rec::parseStillSpec(spec, &p, _error, sizeof _error)) return false;
  SceneSpec s;
  char why[512];
  if (!makeScene(p.scene.c_str(), &s, why, sizeof why)) {
    std::snprintf(_error, sizeof _error, "%s: %s", spec, why);
    return false;
  }
  if (!loadColourImage(p.rgbPath.c_str(), _still->rgb, _error, sizeof _error) ||
      !loadDepthPng16(p.depthPath.c_str(), _still->depthMm, _error, sizeof _error, p.mmPerUnit))
    return false;
  const int w = _still->rgb.width(), h = _still->rgb.height();
  if (w < 32 || h < 32) {
    std::snprintf(_error, sizeof _error, "%s: %dx%d is smaller than 32x32", p.rgbPath.c_str(), w,
                  h);
    return false;
  }
  if (_still->depthMm.width() != w || _still->depthMm.height() != h) {
    std::snprintf(_error, sizeof _error, "%s: depth %dx%d does not match colour %dx%d",
                  p.depthPath.c_str(), _still->depthMm.width(), _still->depthMm.height(), w, h);
    return false;
  }
  s.width = w;
  s.height = h;
  if (p.frames > 0) s.frameCount = p.frames;
  if (opt.maxFrames >= 0 && opt.maxFrames < s.frameCount) s.frameCount = opt.maxFrames;
  if (!placeInStill(&s, _still->depthMm.data(), w, h, p.intrinsics, p.uPx, p.vPx, p.gapMm, why,
                    sizeof why)) {
    std::snprintf(_error, sizeof _error, "%s: %s", spec, why);
    return false;
  }
  // Named by the still's label, the scene and the pixel, e.g.
  // still-tum-fr1-1-flat-turn-250-170.
  char pixel[48];
  std::snprintf(pixel, sizeof pixel, "-%ld-%ld", std::lround(p.uPx), std::lround(p.vPx));
  _name = "still-" + rec::stillLabel(p.rgbPath) + "-" + p.scene + pixel;
  if (!start(s, opt.seed, spec)) return false;
  _scene->setBackdrop(_still->rgb.data(), _still->depthMm.data(), p.intrinsics);
  return true;
}

}  // namespace cuetrack
