// drawScene: one synthetic RGB-D scene from a seed. Every range below is named with where
// it comes from: "OTB" ranges were measured on the development set's 24 real videos
// (docs/recordings.md, "Randomised scenes": target size sqrt(w h) p10-p90 18-168 px at
// 640 px wide, per-frame speed p10-p90 0.5-18 px, aspect w/h p10-p90 0.39-1.17, a median
// scale change of 0.7 % a frame); "Kinect" ranges are what a robot's Kinect v1 sees
// (0.8-4 m working range, objects on or above a floor 0.5-1.3 m below the camera).
#include "cuetrack/drivers/SceneDraw.hpp"

#include <cmath>
#include <cstdio>

#include "DrawRng.hpp"
#include "SynthCommon.hpp"
#include "cuetrack/drivers/StillPlacement.hpp"

namespace cuetrack {

namespace {

using synth::DrawRng;
using synth::kPi;
using Rng = DrawRng;

// The draw's constants, in one place.
constexpr int kFrames = 150;  // 5 s at 30 fps, like the hand-made scenes
constexpr float kFps = 30.f;
constexpr float kSizeMinPx = 18.f, kSizeMaxPx = 168.f;   // OTB p10-p90 of sqrt(w h)
constexpr float kAspectMin = 0.39f, kAspectMax = 1.17f;  // OTB p10-p90 of w / h
constexpr float kSpeedMinPx = 0.5f, kSpeedMaxPx = 18.f;  // OTB p10-p90 px a frame
constexpr float kMaxDriftPx = 1.5f;                      // 35 % of 640 px over the 150 frames
constexpr float kNearMm = 800.f, kFarMm = 4000.f;        // Kinect working range
constexpr float kMinObjectMm = 650.f;                    // nothing nearer (Kinect minimum)

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

// The target's image size and aspect, from the real videos (its metres follow from its
// depth).
struct TargetSize {
  float sizePx, aspect, halfWidthPx, halfHeightPx;
};

TargetSize drawTargetSize(Rng& r) {
  TargetSize t;
  t.sizePx = r.logUniform(kSizeMinPx, kSizeMaxPx);
  t.aspect = r.logUniform(kAspectMin, kAspectMax);
  t.halfWidthPx = 0.5f * t.sizePx * std::sqrt(t.aspect);
  t.halfHeightPx = 0.5f * t.sizePx / std::sqrt(t.aspect);
  return t;
}

// Where the target starts, and the camera and image it is seen in.
struct Backdrop {
  CameraIntrinsics k = kKinectV1Intrinsics;
  int w = 640, h = 480;
  float u0 = 0.f, v0 = 0.f, z0 = 0.f;
};

// The target starts on a pixel of the still with a reading, 100-700 mm in front of the
// real surface there, inside the Kinect's range and in front of the still's surfaces over
// all but one of 9 points of its box: it is seen in the first frame. False when no pixel
// of 64 tries fits.
bool placeOnStill(Rng& r, const StillView& st, const TargetSize& ts, Backdrop* b) {
  for (int tries = 0; tries < 64; ++tries) {
    const float u = r.uniform(0.2f, 0.8f) * st.width, v = r.uniform(0.3f, 0.8f) * st.height;
    const uint16_t surf =
        stillDepthNear(st.depthMm, st.width, st.height, static_cast<int>(u), static_cast<int>(v));
    // The centre stands its half width further in: z + half width = surface - gap.
    const float z =
        (static_cast<float>(surf) - r.uniform(100.f, 700.f)) / (1.f + ts.halfWidthPx / st.k.fx);
    if (surf == 0 || z < kNearMm + 200.f || z > kFarMm) continue;
    int hidden = 0;
    for (int gy = -1; gy <= 1; ++gy)
      for (int gx = -1; gx <= 1; ++gx) {
        const int pu = static_cast<int>(u + 0.8f * gx * ts.halfWidthPx);
        const int pv = static_cast<int>(v + 0.8f * gy * ts.halfHeightPx);
        if (pu < 0 || pv < 0 || pu >= st.width || pv >= st.height) continue;
        const uint16_t dMm = st.depthMm[pv * st.width + pu];
        hidden += dMm != 0 && static_cast<float>(dMm) < z;
      }
    if (hidden > 1) continue;
    b->u0 = u;
    b->v0 = v;
    b->z0 = z;
    b->k = st.k;
    b->w = st.width;
    b->h = st.height;
    return true;
  }
  return false;
}

// The backdrop: each still and the generated room alike likely.
Backdrop drawBackdrop(Rng& r, const StillView* stills, int numStills, const TargetSize& ts,
                      SceneDraw* d) {
  Backdrop b;
  const int pick = static_cast<int>(r.unit() * static_cast<float>(numStills + 1));
  if (stills && pick < numStills && placeOnStill(r, stills[pick], ts, &b)) {
    d->still = pick;
    return b;
  }
  b.u0 = r.uniform(0.25f, 0.75f) * b.w;
  b.v0 = r.uniform(0.3f, 0.75f) * b.h;
  b.z0 = r.uniform(kNearMm + 200.f, 3500.f);
  return b;
}

// The target's shape, size in mm, texture and spin (its motion apart).
SceneObject drawTarget(Rng& r, const TargetSize& ts, const Backdrop& b, bool realTextures,
                       SceneDraw* d, float* widthMm, float* heightMm) {
  SceneObject t;
  t.shape = r.chance(0.5f) ? ShapeKind::Cylinder : ShapeKind::Box;
  const float areaMm = ts.sizePx * b.z0 / b.k.fx;  // sqrt(w h) [mm]
  *widthMm = areaMm * std::sqrt(ts.aspect);
  *heightMm = areaMm / std::sqrt(ts.aspect);
  *widthMm = *widthMm < 40.f ? 40.f : *widthMm;
  *heightMm = *heightMm < 40.f ? 40.f : *heightMm;
  t.radiusMm = *widthMm * 0.5f;
  t.halfDepthMm = t.shape == ShapeKind::Box ? t.radiusMm * r.uniform(0.2f, 1.f) : t.radiusMm;
  t.heightMm = *heightMm;
  t.texture = randomTexture(r, *widthMm);
  d->realTexture[0] = realTextures && r.chance(0.5f);
  d->textureDraw[0] = r.bits();
  if (d->realTexture[0]) t.texture.texelMm = *widthMm * r.uniform(0.9f, 1.3f) / kTextureSize;
  // Spin about the vertical axis: a turn now and then, or a steady spin.
  if (r.chance(0.35f)) {
    d->spin = true;
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
  return t;
}

// The target's motion: a typical image speed from the real videos, shared between a drift
// of at most kMaxDriftPx a frame (a still camera: a faster drift leaves the image within
// the scene) and a sway across a tenth to a third of the image (sine, or triangle: sharp
// turns) at the rest of the speed, plus an approach or a depth sway.
MotionSpec drawTargetMotion(Rng& r, const Backdrop& b, float durationS) {
  MotionSpec m;
  const float z0 = b.z0;
  const float speedPx = r.logUniform(kSpeedMinPx, kSpeedMaxPx);
  const float mmPerPx = z0 / b.k.fx;
  float driftPx = r.unit() * speedPx;
  driftPx = driftPx > kMaxDriftPx ? kMaxDriftPx : driftPx;
  const float angle = r.uniform(0.f, 2.f * kPi);
  m.velocityMmPerS[0] = driftPx * mmPerPx * kFps * std::cos(angle);
  m.velocityMmPerS[1] = 0.4f * driftPx * mmPerPx * kFps * std::sin(angle);  // mostly sideways
  const float swayPxPerS = (speedPx - driftPx) * kFps;
  float swayPx = r.uniform(0.05f, 0.17f) * static_cast<float>(b.w);  // amplitude: +-
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
  return m;
}

// It starts on the drawn pixel and depth; a drift that would leave the image goes the
// other way, and the motion slows until it stays in view (the real videos keep their
// target in the frame).
void keepInView(const Backdrop& b, MotionSpec* mp) {
  MotionSpec& m = *mp;
  const CameraIntrinsics& k = b.k;
  float start[3];
  unproject(k, b.u0, b.v0, b.z0, start);
  auto anchor = [&]() {  // the sways' offset at t = 0 taken out of the start
    float at0[3];
    for (int a = 0; a < 3; ++a) m.startMm[a] = 0.f;
    synth::motionPosition(m, 0.f, at0);
    for (int a = 0; a < 3; ++a) m.startMm[a] = start[a] - at0[a];
  };
  anchor();
  if (!staysInView(m, k, b.w, b.h)) {
    m.velocityMmPerS[0] = -m.velocityMmPerS[0];
    m.velocityMmPerS[1] = -m.velocityMmPerS[1];
  }
  for (int i = 0; i < 12 && !staysInView(m, k, b.w, b.h); ++i) {
    for (int a = 0; a < 3; ++a) {
      m.velocityMmPerS[a] *= 0.75f;
      m.amplitudeMm[a] *= 0.75f;
      m.triangleAmplitudeMm[a] *= 0.75f;
    }
    anchor();
  }
}

// What the distractors need of the target: its motion, start depth and image size.
struct TargetView {
  const SceneObject& t;
  float z0, widthPx, heightPx;
};

// A look-alike twin (the same shape and texture, 0.8-1.25x its size) 300-1500 mm nearer
// or further, crossing the target's path at 1-12 px a frame.
void addTwin(Rng& r, const TargetView& tv, const CameraIntrinsics& k, float durationS,
             SceneDraw* d) {
  SceneSpec& s = d->spec;
  const float z0 = tv.z0;
  SceneObject twin = tv.t;
  const float scale = r.logUniform(0.8f, 1.25f);
  twin.radiusMm *= scale;
  twin.halfDepthMm *= scale;
  twin.heightMm *= scale;
  const float side = r.sign();
  float zTwin = z0 + side * r.uniform(300.f, 1500.f);
  if (zTwin < kNearMm) zTwin = z0 + (z0 - zTwin);
  const float dvPx = r.uniform(-0.4f, 0.4f) * tv.heightPx;
  const float dir = r.sign();
  const float twinSpeedPx = r.logUniform(1.f, 12.f);
  const float tcS = r.uniform(0.25f, 0.75f) * durationS;
  twin.motion = crossing(tv.t.motion, k, tcS, zTwin, twinSpeedPx, dir, dvPx,
                         0.5f * tv.widthPx * (1.f + scale * z0 / zTwin));
  twin.yawRateRadPerS = 0.f;
  twin.yawAmplitudeRad = 0.f;
  s.objects[s.numObjects] = twin;
  d->realTexture[s.numObjects] = d->realTexture[0];
  d->textureDraw[s.numObjects] = d->textureDraw[0];
  ++s.numObjects;
  d->twin = true;
}

// An occluder: a board 0.8-2.5x the target's width, much nearer, passing in front and
// covering some of it for 10-50 frames in all.
void addOccluder(Rng& r, const TargetView& tv, const CameraIntrinsics& k, float durationS,
                 bool realTextures, SceneDraw* d) {
  SceneSpec& s = d->spec;
  const float z0 = tv.z0;
  SceneObject occ;
  occ.shape = ShapeKind::Box;
  float zOcc = z0 * r.uniform(0.35f, 0.75f);
  if (zOcc < kMinObjectMm + 100.f) zOcc = kMinObjectMm + 100.f;
  if (zOcc >= z0 - 150.f) return;
  const float occWidthPx = tv.widthPx * r.uniform(0.8f, 2.5f);
  occ.radiusMm = 0.5f * occWidthPx * zOcc / k.fx;
  occ.halfDepthMm = r.uniform(15.f, 60.f);
  occ.heightMm = tv.heightPx * r.uniform(1.2f, 3.f) * zOcc / k.fy;
  occ.texture = randomTexture(r, occ.radiusMm * 2.f);
  const float frames = r.uniform(10.f, 50.f);
  const float dvPx = r.uniform(-0.3f, 0.3f) * tv.heightPx;
  const float dir = r.sign();
  const float tcS = r.uniform(0.2f, 0.8f) * durationS;
  occ.motion = crossing(tv.t.motion, k, tcS, zOcc, (occWidthPx + tv.widthPx) / frames, dir, dvPx,
                        0.5f * (occWidthPx + tv.widthPx));
  s.objects[s.numObjects] = occ;
  d->realTexture[s.numObjects] = realTextures && r.chance(0.5f);
  d->textureDraw[s.numObjects] = r.bits();
  ++s.numObjects;
  d->occluder = true;
}

// Another object, unlike the target, somewhere else in the room, swaying.
void addOther(Rng& r, const Backdrop& b, bool realTextures, SceneDraw* d) {
  SceneSpec& s = d->spec;
  const CameraIntrinsics& k = b.k;
  SceneObject o;
  o.shape = r.chance(0.5f) ? ShapeKind::Cylinder : ShapeKind::Box;
  const float z = r.uniform(kNearMm + 200.f, kFarMm);
  const float sizeMm = r.logUniform(kSizeMinPx, kSizeMaxPx) * z / k.fx;
  o.radiusMm = 0.5f * sizeMm * r.uniform(0.6f, 1.4f);
  o.halfDepthMm = o.radiusMm;
  o.heightMm = sizeMm * r.uniform(0.6f, 1.8f);
  o.texture = randomTexture(r, 2.f * o.radiusMm);
  const float vPx = r.uniform(0.25f, 0.8f) * b.h;
  const float uPx = r.uniform(0.1f, 0.9f) * b.w;
  unproject(k, uPx, vPx, z, o.motion.startMm);
  o.motion.amplitudeMm[0] = r.uniform(0.f, 400.f);
  o.motion.periodS[0] = r.uniform(2.f, 8.f);
  o.motion.phaseRad[0] = r.uniform(0.f, 2.f * kPi);
  s.objects[s.numObjects] = o;
  d->realTexture[s.numObjects] = realTextures && r.chance(0.5f);
  d->textureDraw[s.numObjects] = r.bits();
  ++s.numObjects;
  d->other = true;
}

// The room (when no still is the backdrop): a wall behind everything, a floor at a
// robot's camera height or none, textures of their own.
void drawRoom(Rng& r, SceneSpec* sp) {
  SceneSpec& s = *sp;
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
}

// Lighting: a slow change, and now and then a step (lights dimmed or switched on).
void drawLighting(Rng& r, SceneSpec* s) {
  if (r.chance(0.25f)) {
    s->lightAmplitude = r.uniform(0.1f, 0.35f);
    s->lightPeriodS = r.uniform(2.f, 5.f);
  }
  if (r.chance(0.15f)) {
    s->lightStepFrame = static_cast<int>(r.uniform(30.f, 120.f));
    s->lightStepGain = r.uniform(0.55f, 1.4f);
  }
  s->colourNoise = r.uniform(1.f, 4.f);
}

// The Kinect: disparity noise, depth lost along the silhouette, a surface it cannot read.
void drawSensor(Rng& r, SceneSpec* s) {
  s->disparityNoiseRaw = r.uniform(0.25f, 0.5f);
  if (r.chance(0.4f)) {
    s->edgeHoleProbability = r.uniform(0.2f, 0.6f);
    s->edgeHoleBandPx = static_cast<int>(r.uniform(2.f, 4.99f));
  }
  if (r.chance(0.15f)) {
    const int len = static_cast<int>(r.uniform(15.f, 60.f));
    s->targetNoDepthFirst = static_cast<int>(r.uniform(10.f, static_cast<float>(kFrames - len)));
    s->targetNoDepthLast = s->targetNoDepthFirst + len - 1;
  }
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

  const TargetSize ts = drawTargetSize(r);
  const Backdrop b = drawBackdrop(r, stills, numStills, ts, &d);
  s.width = b.w;
  s.height = b.h;
  s.intrinsics = b.k;  // a still's own (setBackdrop keeps it); the room's at 640x480

  float widthMm = 0.f, heightMm = 0.f;
  SceneObject t = drawTarget(r, ts, b, realTextures, &d, &widthMm, &heightMm);
  t.motion = drawTargetMotion(r, b, durationS);
  keepInView(b, &t.motion);
  s.objects[0] = t;
  s.numObjects = 1;
  s.targetIndex = 0;
  const TargetView tv{s.objects[0], b.z0, widthMm * b.k.fx / b.z0, heightMm * b.k.fy / b.z0};

  if (r.chance(0.4f)) addTwin(r, tv, b.k, durationS, &d);
  if (r.chance(0.35f)) addOccluder(r, tv, b.k, durationS, realTextures, &d);
  if (s.numObjects < kMaxSceneObjects && r.chance(0.3f)) addOther(r, b, realTextures, &d);
  drawRoom(r, &s);
  drawLighting(r, &s);
  drawSensor(r, &s);
  *out = d;
}

}  // namespace cuetrack
