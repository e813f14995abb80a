// Synthetic RGB-D scenes with exact ground truth: textured upright cylinders and
// boxes moving in 3D before a textured wall and floor, seen by a Kinect-like camera.
//
//   SceneSpec spec;
//   if (!makeScene("twin-crossing", &spec)) ...;   // names: sceneName(i), i < sceneCount()
//   spec.frameCount = 60;                          // optional tweaks
//   static SyntheticSource src(spec, seed);        // ~1.6 MiB: static or allocate once
//   while (src.next(slot) == ReadStatus::Ok) { slot.groundTruth; src.truth().centreMm; }
//
// Deterministic by seed: same spec + seed -> same bytes, on x86-64, aarch64 and armhf
// alike (built with -ffp-contract=off; golden hashes in tests/drivers/test_drivers_synth.cpp).
// No OpenCV, no allocation after construction: it is also the on-board app's embedded
// default source.
//
// Depth model (Kinect v1): true depth -> raw disparity (1/8 px steps, KinectDepth.hpp)
// + Gaussian disparity noise -> rounded -> mm; no reading outside [minDepthMm,
// maxDepthMm] and in the projector's shadow beside near edges (left of near objects,
// the projector sitting baselineMm to the right of the IR camera).
//
// The scenes by name: SceneCatalogue.hpp; what a scene holds: SceneSpec.hpp. The source
// is three files: SyntheticSource.cpp (posing, truth), SceneRaster.cpp (ray casting),
// KinectDepthModel.cpp (the depth reading, colour noise and lighting).
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"
#include "cuetrack/drivers/SceneCatalogue.hpp"
#include "cuetrack/drivers/SceneSpec.hpp"

namespace cuetrack {

// Exact truth for the last frame produced.
struct SynthTruth {
  float centreMm[3] = {0, 0, 0};  // target centre, camera coordinates [mm]
  float radiusMm = 0.f;           // cylinder radius / box half-width [mm]
  float heightMm = 0.f;
  float yawRad = 0.f;  // box yaw at this frame [rad]
  Box projectedBox{};  // bounding box of the whole target's projection, clipped to the image [px]
  int visiblePixels = 0;    // target pixels not hidden by nearer objects
  int projectedPixels = 0;  // target pixels with nothing in front
  float visibleFraction() const {
    return projectedPixels > 0 ? static_cast<float>(visiblePixels) / projectedPixels : 0.f;
  }
};

class SyntheticSource final : public FrameSource {
 public:
  SyntheticSource(const SceneSpec& spec, uint64_t seed);

  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _spec.name; }
  int frameCount() const override { return _spec.frameCount; }
  double nominalFps() const override { return static_cast<double>(_spec.fps); }

  // Renders frame `index` (0-based) without advancing; next() calls it in sequence.
  bool render(int index, FrameSlot& out);
  const SynthTruth& truth() const { return _truth; }
  const SceneSpec& spec() const { return _spec; }
  // Position of object i at time t [s].
  void objectPosition(int i, float tS, float outMm[3]) const;
  // A real registered RGB-D still in place of the procedural wall and floor (the still:
  // source): colour and depth [mm, 0 = no reading] of the spec's width x height, owned by
  // the caller and kept alive, with the still's own intrinsics (not scaled). Objects are
  // drawn over it with a z-test against its depth (a hole hides nothing); its depth stays
  // as it is except where an object covers it or shadows it; colour noise and lighting
  // apply to the whole frame. Call before the first frame.
  void setBackdrop(const Rgb8* rgb, const uint16_t* depthMm, const CameraIntrinsics& k);
  // Object i's texture tile (kTextureSize x kTextureSize, row-major) in place of the one
  // its TextureSpec makes, e.g. a patch of a real video frame. Call before the first frame.
  void setObjectTexture(int i, const Rgb8* tile);

 private:
  using Texture = Rgb8[kTextureSize * kTextureSize];
  struct Posed {
    int index;
    float c[3];
    bool yawed;            // a box with a non-zero yaw at this frame
    float yawRad;          // its yaw; a cylinder's turns its texture
    float cosYaw, sinYaw;  // its rotation (local -> camera: x = c lx - s lz, z = s lx + c lz)
  };

  void renderBackground(FrameSlot& out, uint32_t frameSeed);
  void renderBackdrop(FrameSlot& out);
  void backdropDepthRow(int v, uint16_t* dmm);
  void renderObject(const Posed& p, FrameSlot& out, bool isTarget);
  void applyDepthModel(FrameSlot& out, uint32_t frameSeed);
  void applyEdgeHoles(FrameSlot& out, uint32_t frameSeed);
  float objectYaw(int i, float tS) const;
  Box projectObject(const Posed& p) const;

  SceneSpec _spec;
  uint64_t _seed;
  CameraIntrinsics _k{};
  int _next = 0;
  char _error[160] = "";
  SynthTruth _truth{};
  kinect::RawToMmTable _rawToMm{};
  static constexpr int kColourNoiseLen = 8192;  // >= 2 * 3 * kMaxImageWidth
  float _gaussian[4096];                        // N(0,1) samples, drawn at construction
  int8_t _colourNoise[kColourNoiseLen];         // uniform in [-colourNoise, colourNoise]
  Texture _wallTexture;
  Texture _floorTexture;
  Texture _objectTexture[kMaxSceneObjects];
  float _invFx = 0, _invFy = 0;
  // Per-pixel scratch, fixed: true depth and which object (255 = background) [mm].
  float _zMm[kMaxPixels];
  uint8_t _owner[kMaxPixels];
  float _rowInvZ[kMaxImageWidth];      // depth model scratch, one row [1/mm]
  int32_t _rowRaw[kMaxImageWidth];     // raw disparity of one row before the shadow test
  const Rgb8* _backdropRgb = nullptr;  // setBackdrop: the still, caller-owned
  const uint16_t* _backdropDepthMm = nullptr;
};

}  // namespace cuetrack
