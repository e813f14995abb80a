// Synthetic RGB-D scenes drawn from a seed: a distribution, not a list. Each draw picks
// a backdrop (a real Kinect still the caller offers, or a generated room), the target's
// shape, size and texture, its motion (drift, sways, sharp turns, approach, spin), and,
// each by chance, a look-alike twin at another depth crossing it, an occluder passing in
// front, another object, lighting changes and Kinect depth holes. The ranges are set
// from the development set's real videos and from what a robot's Kinect sees, before any
// tracker was measured on them (docs/recordings.md, "Randomised scenes"); they are not to
// be changed to suit the tracker.
//
//   SceneDraw d;
//   drawScene(17, stills, numStills, /*realTextures=*/true, &d);
//   SyntheticSource src(d.spec, noiseSeed);
//   if (d.still >= 0) src.setBackdrop(rgb[d.still], depth[d.still], stills[d.still].k);
//   for each object i with d.realTexture[i]: src.setObjectTexture(i, tile from d.textureDraw[i])
//
// Pure and deterministic: the same seed and stills give the same scene on every
// architecture (no libm in the draw).
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/drivers/SceneSpec.hpp"

namespace cuetrack {

// A real RGB-D still offered as a backdrop: its depth [mm, 0 = no reading] and intrinsics.
struct StillView {
  const uint16_t* depthMm = nullptr;
  int width = 0, height = 0;
  CameraIntrinsics k{};
};

struct SceneDraw {
  SceneSpec spec;  // named "rand-SEED"; the room's wall and floor unless still >= 0
  int still = -1;  // index into the stills given, or -1: the generated room
  // Objects whose texture is to come from a real video frame (the caller's tiles):
  // textureDraw[i] is the random number that picks the frame and box. Else procedural.
  bool realTexture[kMaxSceneObjects] = {};
  uint32_t textureDraw[kMaxSceneObjects] = {};
  // What was drawn, for the name and for tests.
  bool twin = false, occluder = false, other = false, spin = false;
};

// Draws scene `seed` (any value). stills may be null (numStills 0): the room only.
// realTextures: the caller can supply tiles cut from real video frames.
void drawScene(uint64_t seed, const StillView* stills, int numStills, bool realTextures,
               SceneDraw* out);

}  // namespace cuetrack
