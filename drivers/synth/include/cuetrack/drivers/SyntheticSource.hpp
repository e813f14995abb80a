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
// alike (built with -ffp-contract=off; golden hashes in tests/drivers/test_synth.cpp).
// No OpenCV, no allocation after construction: it is also the on-board app's embedded
// default source.
//
// Depth model (Kinect v1): true depth -> raw disparity (1/8 px steps, KinectDepth.hpp)
// + Gaussian disparity noise -> rounded -> mm; no reading outside [minDepthMm,
// maxDepthMm] and in the projector's shadow beside near edges (left of near objects,
// the projector sitting baselineMm to the right of the IR camera).
#pragma once

#include <cstdint>

#include "cuetrack/core/Config.hpp"
#include "cuetrack/core/Geometry.hpp"
#include "cuetrack/core/Image.hpp"
#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"

namespace cuetrack {

inline constexpr int kMaxSceneObjects = 4;
inline constexpr int kTextureSize = 64;  // texels per side of a procedural texture tile

enum class TextureKind : uint8_t {
  Flat,     // one colour: nothing for appearance features to hold on to
  Patches,  // random coloured rectangles (rich, seeded)
  Stripes,  // horizontal stripes of colour A and B
  Checker,  // checkerboard of colour A and B
};

struct TextureSpec {
  TextureKind kind = TextureKind::Patches;
  Rgb8 colourA{180, 60, 40};
  Rgb8 colourB{40, 90, 200};
  uint32_t seed = 1;    // pattern seed (same seed + kind + colours = same texture)
  float texelMm = 4.f;  // size of one texel on the surface [mm]
};

// Position over time, per axis: start + velocity * t + amplitude * sin(2 pi t / period + phase)
// + triangleAmplitude * tri(t / trianglePeriod + trianglePhase), where tri(f) = 1 - 4 |frac(f) -
// 1/2| runs -1 -> 1 -> -1 over a period (0 and rising at phase 0.25; constant speed 4
// triangleAmplitude / trianglePeriod between the turns). From jumpAtS on (when >= 0) the linear
// part jumps by jumpMm and moves on at jumpVelocityMmPerS: start + velocity * jumpAtS
// + jumpMm + jumpVelocity * (t - jumpAtS) (a teleport, e.g. while out of view). The triangle
// and the jump are off by default (amplitude 0, jumpAtS < 0).
struct MotionSpec {
  float startMm[3] = {0.f, 0.f, 2000.f};  // camera coordinates: x right, y down, z forward [mm]
  float velocityMmPerS[3] = {0.f, 0.f, 0.f};
  float amplitudeMm[3] = {0.f, 0.f, 0.f};
  float periodS[3] = {1.f, 1.f, 1.f};
  float phaseRad[3] = {0.f, 0.f, 0.f};
  float triangleAmplitudeMm[3] = {0.f, 0.f, 0.f};
  float trianglePeriodS[3] = {0.f, 0.f, 0.f};  // <= 0: no triangle term
  float trianglePhase[3] = {0.f, 0.f, 0.f};    // [periods]
  float jumpAtS = -1.f;                        // < 0: no jump
  float jumpMm[3] = {0.f, 0.f, 0.f};
  float jumpVelocityMmPerS[3] = {0.f, 0.f, 0.f};
};

enum class ShapeKind : uint8_t {
  Cylinder,  // upright (axis along camera y)
  Box,       // upright; axis-aligned unless yawed (SceneObject::yawRad, yawRateRadPerS)
};

struct SceneObject {
  ShapeKind shape = ShapeKind::Cylinder;
  float radiusMm = 60.f;     // cylinder radius, or box half-width along x [mm]
  float halfDepthMm = 60.f;  // box half-depth along z [mm] (cylinders: unused)
  float heightMm = 200.f;    // [mm]
  // Boxes: yaw about the vertical (camera y) axis, yawRad + yawRateRadPerS * t
  // + yawAmplitudeRad * sin(2 pi t / yawPeriodS + yawPhaseRad); positive turns the box's +x
  // side away from the camera (towards +z). Cylinders: unused. A yaw of 0 (all zero, the
  // default) renders exactly the axis-aligned box.
  float yawRad = 0.f;
  float yawRateRadPerS = 0.f;
  float yawAmplitudeRad = 0.f;
  float yawPeriodS = 0.f;  // <= 0: no oscillation
  float yawPhaseRad = 0.f;
  MotionSpec motion{};
  TextureSpec texture{};
  bool shaded = true;  // Lambertian shading; off for the untextured scene
};

struct SceneSpec {
  char name[32] = "custom";
  int width = 640;  // [px] <= kMaxImageWidth
  int height = 480;
  int frameCount = 150;
  float fps = 30.f;
  // Intrinsics at 640x480; scaled with the image size.
  CameraIntrinsics intrinsics = kKinectV1Intrinsics;

  // Background: a wall at wallDepthMm spanning x in [wallLeftMm, wallRightMm]
  // (beyond its edges: an opening far out of range), and a floor plane floorYMm
  // below the camera (0 = no floor).
  float wallDepthMm = 4000.f;
  float wallLeftMm = -1400.f;
  float wallRightMm = 4000.f;
  float openingDepthMm = 12000.f;
  float floorYMm = 1000.f;
  TextureSpec wallTexture{TextureKind::Patches, {200, 190, 160}, {90, 110, 80}, 11, 20.f};
  TextureSpec floorTexture{TextureKind::Checker, {150, 120, 90}, {110, 85, 60}, 12, 150.f};

  SceneObject objects[kMaxSceneObjects]{};
  int numObjects = 0;
  int targetIndex = 0;  // the object the ground truth describes

  // Lighting: gain(t) = 1 + lightAmplitude * sin(2 pi t / lightPeriodS), times lightStepGain
  // from lightStepFrame on (when >= 0).
  float lightAmplitude = 0.f;
  float lightPeriodS = 2.f;
  int lightStepFrame = -1;
  float lightStepGain = 1.f;
  float colourNoise = 2.f;  // uniform per-channel sensor noise, +- [0..255 levels]

  // Kinect depth model.
  float disparityNoiseRaw = 0.35f;  // sigma of the disparity noise [raw units = 1/8 px]
  bool shadows = true;
  float baselineMm = 75.f;  // IR projector to camera
  uint16_t minDepthMm = 500;
  uint16_t maxDepthMm = 8000;
  // Edge dropout (the Kinect loses depth along depth edges, beyond the projector's shadow):
  // a pixel within edgeHoleBandPx (Chebyshev distance d, 1..8) of the target's silhouette,
  // on either side of it, reads 0 with probability edgeHoleProbability * (band + 1 - d) / band,
  // drawn per pixel and frame from the seed. 0 (the default): off.
  float edgeHoleProbability = 0.f;
  int edgeHoleBandPx = 3;
  // Frames [targetNoDepthFirst, targetNoDepthLast] the target's own pixels read 0: a black,
  // glossy or sunlit surface the projector's pattern is lost on. -1 (the default): off.
  int targetNoDepthFirst = -1;
  int targetNoDepthLast = -1;
};

// Fills *out with a named scene at 640x480, 150 frames, 30 fps; false for an unknown name.
//   moving        textured cylinder moving in x, y and z before a textured background
//   twin-crossing target and a same-textured twin crossing it 700 mm further back
//   occlusion     a box passes in front of the target, hiding it completely for a while
//   untextured    grey cylinder on a grey wall and floor of the same grey: only depth sees it
//   lighting      moving target under slow brightness change plus a step (lights dimmed)
//   approach      target comes from 4.5 m to 0.8 m: strong perspective scale change
//   box           a textured box moving (shape variety)
//   turn          an elongated box turns 90 degrees from side-on to end-on: image width ~1/3
//   fast          target at 2 m sweeping sideways at 40 px a frame, turning at the image's
//                 sides (a triangle wave): abrupt motion
//   lookalike     a same-textured, slightly smaller cylinder 800 mm nearer passes in front
//                 of the target, pausing over it: hidden completely for 21 frames (65-85)
//   leave-return  target leaves on the right, is out of view for exactly 30 frames (48-77),
//                 comes back from the left edge higher up and stays in view
//   against-surface  a flat box (a bag) slides along a large textured board whose front is
//                 40 mm behind the bag's back: little depth contrast; truth is the bag only
//   held          target moving with a skin-coloured "hand" (a box in front of it) hiding
//                 14-35 % of it
//   flat-turn     a flat box (a book) turns from face-on to 78 degrees and back: image
//                 width changes ~2.6x
//   edge-holes    moving target whose depth drops out on a 3 px band along its silhouette
//                 (edgeHoleProbability), on top of the projector shadow
//   no-depth      moving target whose whole surface reads no depth for 70 frames (40-109):
//                 only colour sees it then (targetNoDepthFirst/Last)
bool makeScene(const char* name, SceneSpec* out);
int sceneCount();
const char* sceneName(int i);  // nullptr when out of range

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

 private:
  using Texture = Rgb8[kTextureSize * kTextureSize];
  struct Posed {
    int index;
    float c[3];
    bool yawed;            // a box with a non-zero yaw at this frame
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
