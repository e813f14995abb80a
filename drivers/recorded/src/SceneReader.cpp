#include "cuetrack/drivers/SceneReader.hpp"

#include <cstdio>

#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

SceneReader::SceneReader() = default;
SceneReader::~SceneReader() = default;

int SceneReader::frameCount() const {
  return _scene ? _scene->frameCount() : -1;
}

double SceneReader::nominalFps() const {
  return _scene ? _scene->nominalFps() : 0.0;
}

bool SceneReader::start(SceneSpec s, uint64_t seed, const char* spec) {
  std::snprintf(s.name, sizeof s.name, "%s", _name.c_str());
  _scene = std::make_unique<SyntheticSource>(s, seed);
  if (_scene->error()[0]) {
    std::snprintf(_error, sizeof _error, "%s: %s", spec, _scene->error());
    _scene.reset();
    return false;
  }
  return true;
}

ReadStatus SceneReader::next(FrameSlot& out) {
  if (!_scene) {
    std::snprintf(_error, sizeof _error, "scene not open");
    return ReadStatus::Error;
  }
  const ReadStatus r = _scene->next(out);
  if (r == ReadStatus::Error) std::snprintf(_error, sizeof _error, "%s", _scene->error());
  return r;
}

}  // namespace cuetrack
