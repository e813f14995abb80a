// A synthetic scene's objects in a real RGB-D still (host only, cuetrack_recorded_cv):
// each frame is the still (colour and depth) with the scene's objects (not its procedural
// wall and floor) drawn over it by SyntheticSource::setBackdrop, a z-test against the
// still's depth (a real surface in front hides them, a hole does not), their depth
// through the synthetic Kinect model (disparity noise, quantisation, the projector's
// shadow, also cast on the still), fresh colour noise per frame, and the scene's exact
// ground truth (the visible target's box). The scene is moved as a whole (placeInStill)
// so that the target's motion start stands on pixel u,v, its back gapMm in front of the
// still's depth there. Spec (openFrameSource, parsed by rec::parseStillSpec):
//   still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]
//   RGB, DEPTH   colour image and 16-bit depth image (PNG or PGM), registered
//   fx,fy,cx,cy  the still's intrinsics [px]
//   mmPerUnit    depth unit in mm (1: mm; 0.2: TUM's value / 5000 m), default 1
//   SCENE        a synth: scene name (makeScene)
//   frames       default the scene's (150), at its 30 fps
// Deterministic by SourceOptions::seed, like the synth: scenes.
#pragma once

#include <memory>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

class SyntheticSource;

class StillSceneReader final : public FrameSource {
 public:
  StillSceneReader();
  ~StillSceneReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override;
  double nominalFps() const override;
  // The scene rendered (truth() for the last frame); nullptr before a successful open().
  const SyntheticSource* scene() const { return _scene.get(); }

 private:
  struct Still;
  std::unique_ptr<Still> _still;  // colour and depth, ~1.5 MiB, read once
  std::unique_ptr<SyntheticSource> _scene;
  std::string _name;
  char _error[768] = "";
};

}  // namespace cuetrack
