// The pan:, still: and rand: source specs (openFrameSource), parsed without reading the still:
// no OpenCV here, so the board builds it and libFuzzer drives it (fuzz_recorded_specs).
// The readers (StillPan.hpp, StillScene.hpp) then load the images and check what needs
// them (the box inside the still, the scene's placement). Each parser returns false with
// one line in err: the spec, then what is wrong with it.
#pragma once

#include <cstddef>
#include <string>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::rec {

// pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames]
inline constexpr int kPanDefaultFrames = 150;
struct PanSpec {
  std::string rgbPath, depthPath;  // colour and 16-bit depth still, registered
  Box box{};                       // the target in the still [px]
  CameraIntrinsics intrinsics{};   // the still's [px]
  float mmPerUnit = 1.f;           // depth unit [mm] (1: mm; 0.2: TUM's value / 5000 m)
  int frames = kPanDefaultFrames;  // at 30 fps
};
bool parsePanSpec(const char* spec, PanSpec* out, char* err, size_t errLen);

// still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]
// Parsed from the right ("@u,v,gapMm[:frames]", then ":SCENE"), so paths may hold '@' or ':'.
struct StillSpec {
  std::string rgbPath, depthPath;  // colour and 16-bit depth still, registered
  CameraIntrinsics intrinsics{};   // the still's [px]
  float mmPerUnit = 1.f;           // depth unit [mm]
  std::string scene;               // a synth: scene name (not checked here: drivers/synth's)
  float uPx = 0.f, vPx = 0.f;      // where the target's motion starts in the still
  float gapMm = 0.f;               // the target's back before the still's surface there
  int frames = -1;                 // -1: the scene's own
};
bool parseStillSpec(const char* spec, StillSpec* out, char* err, size_t errLen);

// rand:SEED[:DATA] (RandomScene.hpp): SEED a decimal number, DATA the shared data folder.
struct RandomSpec {
  unsigned long long seed = 0;
  std::string dataDir;  // empty: the generated room and procedural textures only
};
bool parseRandomSpec(const char* spec, RandomSpec* out, char* err, size_t errLen);

// A still's label for sequence names: the folder above color/ or rgb/ (or its own
// folder) and the image's stem, e.g. "nyu-joinmap-5" for nyu/rgb/joinmap-5.png.
std::string stillLabel(const std::string& rgbPath);

}  // namespace cuetrack::rec
