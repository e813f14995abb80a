// drawScene: one synthetic RGB-D scene from a seed. Every range below is named with where
// it comes from: "OTB" ranges were measured on the development set's 24 real videos
// (docs/recordings.md, "Randomised scenes": target size sqrt(w h) p10-p90 18-168 px at
// 640 px wide, per-frame speed p10-p90 0.5-18 px, aspect w/h p10-p90 0.39-1.17, a median
// scale change of 0.7 % a frame); "Kinect" ranges are what a robot's Kinect v1 sees
// (0.8-4 m working range, objects on or above a floor 0.5-1.3 m below the camera).
#include "cuetrack/drivers/SceneDraw.hpp"

#include <cmath>
#include <cstdio>

#include "SynthCommon.hpp"
#include "cuetrack/drivers/StillPlacement.hpp"

namespace cuetrack {

namespace {

using synth::floorToInt;
using synth::kPi;
using synth::splitmix64;

// The draw's constants, in one place.
constexpr int kFrames = 150;  // 5 s at 30 fps, like the hand-made scenes
constexpr float kFps = 30.f;
constexpr float kSizeMinPx = 18.f, kSizeMaxPx = 168.f;   // OTB p10-p90 of sqrt(w h)
constexpr float kAspectMin = 0.39f, kAspectMax = 1.17f;  // OTB p10-p90 of w / h
constexpr float kSpeedMinPx = 0.5f, kSpeedMaxPx = 18.f;  // OTB p10-p90 px a frame
constexpr float kMaxDriftPx = 1.5f;                      // 35 % of 640 px over the 150 frames
constexpr float kNearMm = 800.f, kFarMm = 4000.f;        // Kinect working range
constexpr float kMinObjectMm = 650.f;                    // nothing nearer (Kinect minimum)

// 2^x and log2(x) without libm, so a draw is the same on every architecture (the library
// is built with -ffp-contract=off).
float exp2Det(float x) {
  const int n = floorToInt(x);
  const float y = (x - static_cast<float>(n)) * 0.69314718f;
  float term = 1.f, sum = 1.f;
  for (int k = 1; k <= 9; ++k) {
    term *= y / static_cast<float>(k);
    sum += term;
  }
  for (int i = 0; i < n; ++i) sum *= 2.f;
  for (int i = 0; i > n; --i) sum *= 0.5f;
  return sum;
}

float log2Det(float x) {
  int n = 0;
  while (x >= 2.f) {
    x *= 0.5f;
    ++n;
  }
  while (x < 1.f) {
    x *= 2.f;
    --n;
  }
  // ln x = 2 atanh((x - 1) / (x + 1)), z <= 1/3 here.
  const float z = (x - 1.f) / (x + 1.f), z2 = z * z;
  float t = z, s = 0.f;
  for (int k = 0; k < 10; ++k) {
    s += t / static_cast<float>(2 * k + 1);
    t *= z2;
  }
  return static_cast<float>(n) + 2.f * s / 0.69314718f;
}

struct Rng {
  uint64_t s;
  float unit() { return static_cast<float>(splitmix64(s) >> 40) * (1.f / 16777216.f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
  float logUniform(float lo, float hi) { return lo * exp2Det(unit() * log2Det(hi / lo)); }
  bool chance(float p) { return unit() < p; }
  float sign() { return chance(0.5f) ? 1.f : -1.f; }
  uint32_t bits() { return static_cast<uint32_t>(splitmix64(s) >> 32); }
  uint8_t byte() { return static_cast<uint8_t>(splitmix64(s) >> 56); }
};

Rgb8 randomColour(Rng& r) {
  return {r.byte(), r.byte(), r.byte()};
}

// A procedural texture: mostly patches (rich), some stripes or checks, some flat (nothing
// for appearance to hold on to); one tile spans 0.5-2 object widths.
TextureSpec randomTexture(Rng& r, float widthMm) {
  TextureSpec t;
  const float k = r.unit();
  t.kind = k < 0.55f   ? TextureKind::Patches
           : k < 0.72f ? TextureKind::Stripes
           : k < 0.88f ? TextureKind::Checker
                       : TextureKind::Flat;
  t.colourA = randomColour(r);
  t.colourB = randomColour(r);
  t.seed = r.bits() | 1u;
  t.texelMm = widthMm * r.logUniform(0.5f, 2.f) / static_cast<float>(kTextureSize);
  return t;
}

// The pixel an object centre projects to.
void project(const CameraIntrinsics& k, const float p[3], float* u, float* v) {
  *u = k.cx + k.fx * p[0] / p[2];
  *v = k.cy + k.fy * p[1] / p[2];
}

// Camera coordinates of pixel (u, v) at depth z.
void unproject(const CameraIntrinsics& k, float u, float v, float z, float out[3]) {
  out[0] = (u - k.cx) / k.fx * z;
  out[1] = (v - k.cy) / k.fy * z;
  out[2] = z;
}

// True when the object's centre stays in the middle 84 % x 80 % of the image and in
// [kMinObjectMm, 6 m] for the whole scene.
bool staysInView(const MotionSpec& m, const CameraIntrinsics& k, int w, int h) {
  for (int f = 0; f < kFrames; f += 3) {
    float p[3], u, v;
    synth::motionPosition(m, static_cast<float>(f) / kFps, p);
    if (p[2] < kMinObjectMm || p[2] > 6000.f) return false;
    project(k, p, &u, &v);
    if (u < 0.08f * w || u > 0.92f * w || v < 0.1f * h || v > 0.9f * h) return false;
  }
  return true;
}

// An object that passes the target's centre at time tcS, at depth zMm, moving sideways
// at speedPx a frame in the image (direction dir = +-1), dvPx below the target's centre.
// It passes later when it would cover the target at the start (its half width and the
// target's, in px: halfSumPx), so that the first frame shows the target whole.
MotionSpec crossing(const MotionSpec& target, const CameraIntrinsics& k, float tcS, float zMm,
                    float speedPx, float dir, float dvPx, float halfSumPx) {
  MotionSpec m;
  for (int tries = 0; tries < 16; ++tries) {
    float at[3], u, v;
    synth::motionPosition(target, tcS, at);
    project(k, at, &u, &v);
    float pass[3];
    unproject(k, u, v + dvPx, zMm, pass);
    const float vx = dir * speedPx * zMm / k.fx * kFps;
    m.velocityMmPerS[0] = vx;
    m.startMm[0] = pass[0] - vx * tcS;
    m.startMm[1] = pass[1];
    m.startMm[2] = zMm;
    float t0[3], o0[3], ut, vt, uo, vo;
    synth::motionPosition(target, 0.f, t0);
    synth::motionPosition(m, 0.f, o0);
    project(k, t0, &ut, &vt);
    project(k, o0, &uo, &vo);
    if (std::fabs(uo - ut) > halfSumPx + 4.f) break;
    tcS += 0.5f * (halfSumPx + 4.f) / (speedPx * kFps);
  }
  return m;
}

}  // namespace

void drawScene(uint64_t seed, const StillView* stills, int numStills, bool realTextures,
               SceneDraw* out) {
  SceneDraw d;
  Rng r{seed * 0x9E3779B97F4A7C15ull ^ 0x5CE4EDull};
  SceneSpec& s = d.spec;
  std::snprintf(s.name, sizeof s.name, "rand-%llu", static_cast<unsigned long long>(seed));
  s.frameCount = kFrames;
  s.fps = kFps;
  const float durationS = kFrames / kFps;

  // The target's image size and aspect, from the real videos (its metres follow from its
  // depth below).
  const float sizePx = r.logUniform(kSizeMinPx, kSizeMaxPx);
  const float aspect = r.logUniform(kAspectMin, kAspectMax);
  const float halfWidthPx = 0.5f * sizePx * std::sqrt(aspect);
  const float halfHeightPx = 0.5f * sizePx / std::sqrt(aspect);

  // The backdrop: each still and the generated room alike likely.
  const int pick = static_cast<int>(r.unit() * static_cast<float>(numStills + 1));
  CameraIntrinsics k = kKinectV1Intrinsics;
  int w = 640, h = 480;
  float u0 = 0.f, v0 = 0.f, z0 = 0.f;  // where the target starts
  bool placed = false;
  if (stills && pick < numStills) {
    // The target starts on a pixel of the still with a reading, 100-700 mm in front of the
    // real surface there, inside the Kinect's range and in front of the still's surfaces
    // over all but one of 9 points of its box: it is seen in the first frame.
    const StillView& st = stills[pick];
    for (int tries = 0; tries < 64 && !placed; ++tries) {
      const float u = r.uniform(0.2f, 0.8f) * st.width, v = r.uniform(0.3f, 0.8f) * st.height;
      const uint16_t surf =
          stillDepthNear(st.depthMm, st.width, st.height, static_cast<int>(u), static_cast<int>(v));
      // The centre stands its half width further in: z + half width = surface - gap.
      const float z =
          (static_cast<float>(surf) - r.uniform(100.f, 700.f)) / (1.f + halfWidthPx / st.k.fx);
      if (surf == 0 || z < kNearMm + 200.f || z > kFarMm) continue;
      int hidden = 0;
      for (int gy = -1; gy <= 1; ++gy)
        for (int gx = -1; gx <= 1; ++gx) {
          const int pu = static_cast<int>(u + 0.8f * gx * halfWidthPx);
          const int pv = static_cast<int>(v + 0.8f * gy * halfHeightPx);
          if (pu < 0 || pv < 0 || pu >= st.width || pv >= st.height) continue;
          const uint16_t dMm = st.depthMm[pv * st.width + pu];
          hidden += dMm != 0 && static_cast<float>(dMm) < z;
        }
      if (hidden > 1) continue;
      u0 = u;
      v0 = v;
      z0 = z;
      placed = true;
    }
    if (placed) {
      d.still = pick;
      k = st.k;
      w = st.width;
      h = st.height;
    }
  }
  if (!placed) {
    u0 = r.uniform(0.25f, 0.75f) * w;
    v0 = r.uniform(0.3f, 0.75f) * h;
    z0 = r.uniform(kNearMm + 200.f, 3500.f);
  }
  s.width = w;
  s.height = h;
  s.intrinsics = k;  // a still's own (setBackdrop keeps it); the room's at 640x480

  // The target.
  SceneObject t;
  t.shape = r.chance(0.5f) ? ShapeKind::Cylinder : ShapeKind::Box;
  const float areaMm = sizePx * z0 / k.fx;  // sqrt(w h) [mm]
  float widthMm = areaMm * std::sqrt(aspect);
  float heightMm = areaMm / std::sqrt(aspect);
  widthMm = widthMm < 40.f ? 40.f : widthMm;
  heightMm = heightMm < 40.f ? 40.f : heightMm;
  t.radiusMm = widthMm * 0.5f;
  t.halfDepthMm = t.shape == ShapeKind::Box ? t.radiusMm * r.uniform(0.2f, 1.f) : t.radiusMm;
  t.heightMm = heightMm;
  t.texture = randomTexture(r, widthMm);
  d.realTexture[0] = realTextures && r.chance(0.5f);
  d.textureDraw[0] = r.bits();
  if (d.realTexture[0]) t.texture.texelMm = widthMm * r.uniform(0.9f, 1.3f) / kTextureSize;
  // Spin about the vertical axis: a turn now and then, or a steady spin.
  if (r.chance(0.35f)) {
    d.spin = true;
    if (r.chance(0.5f)) {
      // Each draw its own statement: the order of a call's arguments or an operator's
      // operands is unspecified, and differs between compilers' targets.
      const float sign = r.sign();
      t.yawRateRadPerS = sign * r.uniform(0.4f, 2.f);
    } else {
      t.yawAmplitudeRad = r.uniform(0.4f, 1.2f);
      t.yawPeriodS = r.uniform(2.f, 6.f);
      t.yawPhaseRad = r.uniform(0.f, 2.f * kPi);
    }
  }

  // Its motion: a typical image speed from the real videos, shared between a drift of at
  // most kMaxDriftPx a frame (a still camera: a faster drift leaves the image within the
  // scene) and a sway across a tenth to a third of the image (sine, or triangle: sharp
  // turns) at the rest of the speed, plus an approach or a depth sway.
  MotionSpec m;
  const float speedPx = r.logUniform(kSpeedMinPx, kSpeedMaxPx);
  const float mmPerPx = z0 / k.fx;
  float driftPx = r.unit() * speedPx;
  driftPx = driftPx > kMaxDriftPx ? kMaxDriftPx : driftPx;
  const float angle = r.uniform(0.f, 2.f * kPi);
  m.velocityMmPerS[0] = driftPx * mmPerPx * kFps * std::cos(angle);
  m.velocityMmPerS[1] = 0.4f * driftPx * mmPerPx * kFps * std::sin(angle);  // mostly sideways
  const float swayPxPerS = (speedPx - driftPx) * kFps;
  float swayPx = r.uniform(0.05f, 0.17f) * static_cast<float>(w);  // amplitude: +-
  const bool triangle = r.chance(0.3f);
  // The period that gives the sway's mean speed (sine and triangle alike: 4 A / P), at
  // most 8 s (then a smaller sway).
  float periodS = swayPxPerS > 0.f ? 4.f * swayPx / swayPxPerS : 8.f;
  if (periodS > 8.f) {
    periodS = 8.f;
    swayPx = swayPxPerS * periodS / 4.f;
  }
  if (periodS < 0.4f) periodS = 0.4f;
  if (triangle) {
    m.trianglePeriodS[0] = periodS;
    m.triangleAmplitudeMm[0] = swayPx * mmPerPx;
    m.trianglePhase[0] = r.unit();
  } else {
    m.periodS[0] = periodS;
    m.amplitudeMm[0] = swayPx * mmPerPx;
    m.phaseRad[0] = r.uniform(0.f, 2.f * kPi);
  }
  m.periodS[1] = periodS * r.uniform(0.7f, 1.5f);  // up and down: up to half as far
  m.amplitudeMm[1] = r.uniform(0.f, 0.5f) * swayPx * mmPerPx;
  m.phaseRad[1] = r.uniform(0.f, 2.f * kPi);
  const float depthKind = r.unit();
  if (depthKind < 0.35f) {
    // Approach or recede: the image size changes 0.55-1.8x over the scene.
    const float ratio = r.logUniform(0.55f, 1.8f);
    m.velocityMmPerS[2] = z0 * (1.f / ratio - 1.f) / durationS;
  } else if (depthKind < 0.7f) {
    m.amplitudeMm[2] = r.uniform(0.1f, 0.3f) * z0;
    m.periodS[2] = r.uniform(2.f, 6.f);
    m.phaseRad[2] = r.uniform(0.f, 2.f * kPi);
  }
  // It starts on the drawn pixel and depth; a drift that would leave the image goes the
  // other way, and the motion slows until it stays in view (the real videos keep their
  // target in the frame).
  float start[3];
  unproject(k, u0, v0, z0, start);
  auto anchor = [&]() {  // the sways' offset at t = 0 taken out of the start
    float at0[3];
    for (int a = 0; a < 3; ++a) m.startMm[a] = 0.f;
    synth::motionPosition(m, 0.f, at0);
    for (int a = 0; a < 3; ++a) m.startMm[a] = start[a] - at0[a];
  };
  anchor();
  if (!staysInView(m, k, w, h)) {
    m.velocityMmPerS[0] = -m.velocityMmPerS[0];
    m.velocityMmPerS[1] = -m.velocityMmPerS[1];
  }
  for (int i = 0; i < 12 && !staysInView(m, k, w, h); ++i) {
    for (int a = 0; a < 3; ++a) {
      m.velocityMmPerS[a] *= 0.75f;
      m.amplitudeMm[a] *= 0.75f;
      m.triangleAmplitudeMm[a] *= 0.75f;
    }
    anchor();
  }
  t.motion = m;
  s.objects[0] = t;
  s.numObjects = 1;
  s.targetIndex = 0;
  const float targetWidthPx = widthMm * k.fx / z0;
  const float targetHeightPx = heightMm * k.fy / z0;

  // A look-alike twin (the same shape and texture, 0.8-1.25x its size) 300-1500 mm nearer
  // or further, crossing the target's path at 1-12 px a frame.
  if (r.chance(0.4f)) {
    SceneObject twin = t;
    const float scale = r.logUniform(0.8f, 1.25f);
    twin.radiusMm *= scale;
    twin.halfDepthMm *= scale;
    twin.heightMm *= scale;
    const float side = r.sign();
    float zTwin = z0 + side * r.uniform(300.f, 1500.f);
    if (zTwin < kNearMm) zTwin = z0 + (z0 - zTwin);
    const float dvPx = r.uniform(-0.4f, 0.4f) * targetHeightPx;
    const float dir = r.sign();
    const float twinSpeedPx = r.logUniform(1.f, 12.f);
    const float tcS = r.uniform(0.25f, 0.75f) * durationS;
    twin.motion = crossing(m, k, tcS, zTwin, twinSpeedPx, dir, dvPx,
                           0.5f * targetWidthPx * (1.f + scale * z0 / zTwin));
    twin.yawRateRadPerS = 0.f;
    twin.yawAmplitudeRad = 0.f;
    s.objects[s.numObjects] = twin;
    d.realTexture[s.numObjects] = d.realTexture[0];
    d.textureDraw[s.numObjects] = d.textureDraw[0];
    ++s.numObjects;
    d.twin = true;
  }
  // An occluder: a board 0.8-2.5x the target's width, much nearer, passing in front and
  // covering some of it for 10-50 frames in all.
  if (r.chance(0.35f)) {
    SceneObject occ;
    occ.shape = ShapeKind::Box;
    float zOcc = z0 * r.uniform(0.35f, 0.75f);
    if (zOcc < kMinObjectMm + 100.f) zOcc = kMinObjectMm + 100.f;
    if (zOcc < z0 - 150.f) {
      const float occWidthPx = targetWidthPx * r.uniform(0.8f, 2.5f);
      occ.radiusMm = 0.5f * occWidthPx * zOcc / k.fx;
      occ.halfDepthMm = r.uniform(15.f, 60.f);
      occ.heightMm = targetHeightPx * r.uniform(1.2f, 3.f) * zOcc / k.fy;
      occ.texture = randomTexture(r, occ.radiusMm * 2.f);
      const float frames = r.uniform(10.f, 50.f);
      const float dvPx = r.uniform(-0.3f, 0.3f) * targetHeightPx;
      const float dir = r.sign();
      const float tcS = r.uniform(0.2f, 0.8f) * durationS;
      occ.motion = crossing(m, k, tcS, zOcc, (occWidthPx + targetWidthPx) / frames, dir, dvPx,
                            0.5f * (occWidthPx + targetWidthPx));
      s.objects[s.numObjects] = occ;
      d.realTexture[s.numObjects] = realTextures && r.chance(0.5f);
      d.textureDraw[s.numObjects] = r.bits();
      ++s.numObjects;
      d.occluder = true;
    }
  }
  // Another object, unlike the target, somewhere else in the room, swaying.
  if (s.numObjects < kMaxSceneObjects && r.chance(0.3f)) {
    SceneObject o;
    o.shape = r.chance(0.5f) ? ShapeKind::Cylinder : ShapeKind::Box;
    const float z = r.uniform(kNearMm + 200.f, kFarMm);
    const float sizeMm = r.logUniform(kSizeMinPx, kSizeMaxPx) * z / k.fx;
    o.radiusMm = 0.5f * sizeMm * r.uniform(0.6f, 1.4f);
    o.halfDepthMm = o.radiusMm;
    o.heightMm = sizeMm * r.uniform(0.6f, 1.8f);
    o.texture = randomTexture(r, 2.f * o.radiusMm);
    const float vPx = r.uniform(0.25f, 0.8f) * h;
    const float uPx = r.uniform(0.1f, 0.9f) * w;
    unproject(k, uPx, vPx, z, o.motion.startMm);
    o.motion.amplitudeMm[0] = r.uniform(0.f, 400.f);
    o.motion.periodS[0] = r.uniform(2.f, 8.f);
    o.motion.phaseRad[0] = r.uniform(0.f, 2.f * kPi);
    s.objects[s.numObjects] = o;
    d.realTexture[s.numObjects] = realTextures && r.chance(0.5f);
    d.textureDraw[s.numObjects] = r.bits();
    ++s.numObjects;
    d.other = true;
  }

  // The room (when no still is the backdrop): a wall behind everything, a floor at a
  // robot's camera height or none, textures of their own.
  float farthestMm = 0.f;
  for (int i = 0; i < s.numObjects; ++i)
    for (int f = 0; f < kFrames; f += 5) {
      float p[3];
      synth::motionPosition(s.objects[i].motion, static_cast<float>(f) / kFps, p);
      farthestMm = p[2] > farthestMm ? p[2] : farthestMm;
    }
  s.wallDepthMm = r.uniform(2500.f, 6000.f);
  if (s.wallDepthMm < farthestMm + 500.f) s.wallDepthMm = farthestMm + 500.f;
  s.wallLeftMm = -r.uniform(800.f, 3000.f);
  s.wallRightMm = r.uniform(800.f, 4000.f);
  s.floorYMm = r.chance(0.8f) ? r.uniform(500.f, 1300.f) : 0.f;
  s.wallTexture = randomTexture(r, 1500.f);
  if (s.wallTexture.kind == TextureKind::Flat) s.wallTexture.kind = TextureKind::Patches;
  s.floorTexture = {TextureKind::Checker, randomColour(r), randomColour(r), r.bits() | 1u,
                    r.uniform(80.f, 200.f)};

  // Lighting: a slow change, and now and then a step (lights dimmed or switched on).
  if (r.chance(0.25f)) {
    s.lightAmplitude = r.uniform(0.1f, 0.35f);
    s.lightPeriodS = r.uniform(2.f, 5.f);
  }
  if (r.chance(0.15f)) {
    s.lightStepFrame = static_cast<int>(r.uniform(30.f, 120.f));
    s.lightStepGain = r.uniform(0.55f, 1.4f);
  }
  s.colourNoise = r.uniform(1.f, 4.f);
  // The Kinect: disparity noise, depth lost along the silhouette, a surface it cannot read.
  s.disparityNoiseRaw = r.uniform(0.25f, 0.5f);
  if (r.chance(0.4f)) {
    s.edgeHoleProbability = r.uniform(0.2f, 0.6f);
    s.edgeHoleBandPx = static_cast<int>(r.uniform(2.f, 4.99f));
  }
  if (r.chance(0.15f)) {
    const int len = static_cast<int>(r.uniform(15.f, 60.f));
    s.targetNoDepthFirst = static_cast<int>(r.uniform(10.f, static_cast<float>(kFrames - len)));
    s.targetNoDepthLast = s.targetNoDepthFirst + len - 1;
  }
  *out = d;
}

}  // namespace cuetrack
