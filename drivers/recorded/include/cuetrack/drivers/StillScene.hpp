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

#include "cuetrack/drivers/SceneReader.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

class StillSceneReader final : public SceneReader {
 public:
  StillSceneReader();
  ~StillSceneReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});

 private:
  struct Still;
  std::unique_ptr<Still> _still;  // colour and depth, ~1.5 MiB, read once
};

}  // namespace cuetrack
