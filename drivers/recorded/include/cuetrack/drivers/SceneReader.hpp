// What the readers of synthetic scenes over real stills share (still: StillScene.hpp,
// rand: RandomScene.hpp; host only, cuetrack_recorded_cv): the rendered scene, its name
// and error line. Each reader's open() builds the spec and calls start(); frames and
// counts come from the scene.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/SceneSpec.hpp"

namespace cuetrack {

class SyntheticSource;

class SceneReader : public FrameSource {
 public:
  ~SceneReader() override;
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override;
  double nominalFps() const override;
  // The scene rendered (truth() for the last frame); nullptr before a successful open().
  const SyntheticSource* scene() const { return _scene.get(); }

 protected:
  SceneReader();
  // The scene of spec s named _name, noise by seed; false with "SPEC: reason" in _error.
  bool start(SceneSpec s, uint64_t seed, const char* spec);

  std::unique_ptr<SyntheticSource> _scene;
  std::string _name;
  char _error[768] = "";
};

}  // namespace cuetrack
