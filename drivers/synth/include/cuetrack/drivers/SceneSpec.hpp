// What a synthetic scene is made of: textured upright cylinders and boxes with their
// motion, a textured wall and floor, the lighting and the Kinect depth model's settings.
// SyntheticSource renders one; the catalogue (SceneCatalogue.hpp) names the built-in ones.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"

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
  // side away from the camera (towards +z). Cylinders: the texture turns with it (a spin).
  // A yaw of 0 (all zero, the default) renders exactly the axis-aligned box.
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

}  // namespace cuetrack
