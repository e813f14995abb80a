// Ray casting of a few convex objects per frame: only each object's projected
// bounding box is visited, the background is analytic (wall, floor, opening), so a
// 640x480 frame costs about one pass of arithmetic per pixel plus the depth model.
#include "cuetrack/drivers/SyntheticSource.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace cuetrack {

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr uint8_t kBackgroundOwner = 255;
constexpr float kHoleZMm = 1e9f;  // a still's pixel without a reading: nothing is behind it

uint64_t splitmix64(uint64_t& s) {
  uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// xorshift32: tiny and fast; state must never be 0.
struct Rng32 {
  uint32_t s;
  explicit Rng32(uint32_t seed) : s(seed ? seed : 0x9E3779B9u) {}
  uint32_t next() {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return s;
  }
  int range(int lo, int hi) {
    return lo + static_cast<int>(next() % static_cast<uint32_t>(hi - lo + 1));
  }
};

uint8_t clampByte(float v) {
  if (v <= 0.f) return 0;
  if (v >= 255.f) return 255;
  return static_cast<uint8_t>(v + 0.5f);
}

Rgb8 mix(Rgb8 a, Rgb8 b, float w) {
  return {clampByte(a.r + (b.r - a.r) * w), clampByte(a.g + (b.g - a.g) * w),
          clampByte(a.b + (b.b - a.b) * w)};
}

void makeTexture(const TextureSpec& t, Rgb8* tex) {
  const int n = kTextureSize;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      Rgb8 c = t.colourA;
      if (t.kind == TextureKind::Stripes) c = ((y / 8) & 1) ? t.colourB : t.colourA;
      if (t.kind == TextureKind::Checker) c = (((x / 8) ^ (y / 8)) & 1) ? t.colourB : t.colourA;
      tex[y * n + x] = c;
    }
  }
  if (t.kind != TextureKind::Patches) return;
  // Random rectangles, wrapping so the tile repeats seamlessly.
  Rng32 rng(t.seed * 2654435761u + 17u);
  for (int i = 0; i < 40; ++i) {
    const int w = rng.range(3, 22), h = rng.range(3, 22);
    const int x0 = rng.range(0, n - 1), y0 = rng.range(0, n - 1);
    Rgb8 c;
    const uint32_t pick = rng.next() % 4;
    if (pick == 0) {
      c = t.colourB;
    } else if (pick == 1) {
      c = mix(t.colourA, t.colourB, static_cast<float>(rng.range(0, 100)) / 100.f);
    } else if (pick == 2) {
      c = {static_cast<uint8_t>(rng.range(0, 255)), static_cast<uint8_t>(rng.range(0, 255)),
           static_cast<uint8_t>(rng.range(0, 255))};
    } else {
      const uint8_t g = static_cast<uint8_t>(rng.range(20, 240));
      c = {g, g, g};
    }
    for (int y = y0; y < y0 + h; ++y)
      for (int x = x0; x < x0 + w; ++x) tex[(y % n) * n + (x % n)] = c;
  }
}

// floor() without the libm call that baseline x86-64 makes of std::floor.
inline int floorToInt(float v) {
  const int i = static_cast<int>(v);
  return i - (static_cast<float>(i) > v);
}

inline Rgb8 sample(const Rgb8* tex, float sMm, float tMm, float invTexelMm) {
  const int ix = floorToInt(sMm * invTexelMm) & (kTextureSize - 1);
  const int iy = floorToInt(tMm * invTexelMm) & (kTextureSize - 1);
  return tex[iy * kTextureSize + ix];
}

// Light from the upper left, in front of the scene (unit vector towards the light).
constexpr float kLight[3] = {-0.4082f, -0.4082f, -0.8165f};

inline Rgb8 shade(Rgb8 c, float nx, float ny, float nz) {
  float d = nx * kLight[0] + ny * kLight[1] + nz * kLight[2];
  if (d < 0.f) d = 0.f;
  const float k = 0.45f + 0.55f * d;
  return {clampByte(c.r * k), clampByte(c.g * k), clampByte(c.b * k)};
}

// Ray-slab clipping: the ray is inside the slab for t in [a, b] (either order); narrows
// [tn, tf] to it and remembers which slab the ray enters last (the face it hits).
inline void clipSlab(float a, float b, int slabFace, float* tn, float* tf, int* face) {
  if (a > b) {
    const float tmp = a;
    a = b;
    b = tmp;
  }
  if (a > *tn) {
    *tn = a;
    *face = slabFace;
  }
  if (b < *tf) *tf = b;
}

constexpr const char* kSceneNames[] = {
    "moving", "twin-crossing", "occlusion",  "untextured", "lighting",     "approach",
    "box",    "turn",          "fast",       "lookalike",  "leave-return", "against-surface",
    "held",   "flat-turn",     "edge-holes", "no-depth"};
constexpr int kNumScenes = static_cast<int>(sizeof(kSceneNames) / sizeof(kSceneNames[0]));

// leave-return: the target's box is empty from frame kLeaveFirst to kLeaveFirst + 29; the
// jump happens half a frame before kLeaveFirst + 30.
constexpr int kLeaveFirst = 48;
constexpr float kLeaveReturnJumpFrame = kLeaveFirst + 30 - 0.5f;
constexpr float kLeaveReturnJumpXMm = -3290.f;  // back at x = -1277.5 mm: 1/3 in view

SceneObject texturedCylinder() {
  SceneObject o;
  o.shape = ShapeKind::Cylinder;
  o.radiusMm = 80.f;
  o.heightMm = 260.f;
  o.texture = {TextureKind::Patches, {200, 40, 40}, {30, 60, 190}, 101, 5.f};
  return o;
}

// An upright box halfWidthMm either side in x, halfDepthMm in z, heightMm tall.
SceneObject texturedBox(float halfWidthMm, float halfDepthMm, float heightMm,
                        const TextureSpec& texture) {
  SceneObject o;
  o.shape = ShapeKind::Box;
  o.radiusMm = halfWidthMm;
  o.halfDepthMm = halfDepthMm;
  o.heightMm = heightMm;
  o.texture = texture;
  return o;
}

// Where a motion starts, camera coordinates [mm].
void startAt(MotionSpec* m, float xMm, float yMm, float zMm) {
  m->startMm[0] = xMm;
  m->startMm[1] = yMm;
  m->startMm[2] = zMm;
}

// Carried around at 2 m: sways of xAmplitudeMm across (5 s), 60 mm up and down (3 s) and
// 300 mm in depth (6 s).
void carriedAround(MotionSpec* m, float xAmplitudeMm) {
  startAt(m, -100.f, 200.f, 2000.f);
  m->amplitudeMm[0] = xAmplitudeMm;
  m->periodS[0] = 5.f;
  m->amplitudeMm[1] = 60.f;
  m->periodS[1] = 3.f;
  m->amplitudeMm[2] = 300.f;
  m->periodS[2] = 6.f;
}

}  // namespace

int sceneCount() {
  return kNumScenes;
}

const char* sceneName(int i) {
  return (i >= 0 && i < kNumScenes) ? kSceneNames[i] : nullptr;
}

bool makeScene(const char* name, SceneSpec* out) {
  if (!name || !out) return false;
  int which = -1;
  for (int i = 0; i < kNumScenes; ++i)
    if (std::strcmp(name, kSceneNames[i]) == 0) which = i;
  if (which < 0) return false;
  SceneSpec s;
  std::snprintf(s.name, sizeof s.name, "%s", name);
  SceneObject t = texturedCylinder();
  const std::string_view n(kSceneNames[which]);
  if (n == "moving" || n == "lighting") {
    startAt(&t.motion, -100.f, 200.f, 2200.f);
    t.motion.amplitudeMm[0] = 600.f;
    t.motion.periodS[0] = 4.f;
    t.motion.amplitudeMm[1] = 80.f;
    t.motion.periodS[1] = 3.f;
    t.motion.amplitudeMm[2] = 600.f;
    t.motion.periodS[2] = 6.f;
    t.motion.phaseRad[2] = 1.f;
    s.objects[0] = t;
    s.numObjects = 1;
    if (n == "lighting") {
      s.lightAmplitude = 0.35f;
      s.lightPeriodS = 3.f;
      s.lightStepFrame = 75;
      s.lightStepGain = 0.55f;
    }
  } else if (n == "twin-crossing") {
    // Target left -> right at 1.8 m; its twin right -> left at 2.5 m; both at x = 0 at t = 2.5 s.
    startAt(&t.motion, -900.f, 200.f, 1800.f);
    t.motion.velocityMmPerS[0] = 360.f;
    SceneObject twin = t;
    startAt(&twin.motion, 1100.f, 250.f, 2500.f);
    twin.motion.velocityMmPerS[0] = -440.f;
    s.objects[0] = t;
    s.objects[1] = twin;
    s.numObjects = 2;
  } else if (n == "occlusion") {
    // A wide striped box at 1.2 m sweeps across and hides the target completely mid-way.
    startAt(&t.motion, -200.f, 200.f, 2200.f);
    t.motion.velocityMmPerS[0] = 80.f;
    SceneObject occ = texturedBox(220.f, 50.f, 600.f,
                                  {TextureKind::Stripes, {60, 160, 60}, {230, 230, 80}, 7, 6.f});
    startAt(&occ.motion, -1300.f, 110.f, 1200.f);
    occ.motion.velocityMmPerS[0] = 500.f;
    s.objects[0] = t;
    s.objects[1] = occ;
    s.numObjects = 2;
  } else if (n == "untextured") {
    const Rgb8 grey{128, 128, 128};
    s.wallTexture = {TextureKind::Flat, grey, grey, 1, 20.f};
    s.floorTexture = {TextureKind::Flat, grey, grey, 1, 20.f};
    s.wallLeftMm = -20000.f;  // no opening either: one grey everywhere
    t.texture = {TextureKind::Flat, grey, grey, 1, 5.f};
    t.shaded = false;
    startAt(&t.motion, -100.f, 200.f, 2000.f);
    t.motion.amplitudeMm[0] = 500.f;
    t.motion.periodS[0] = 4.f;
    t.motion.amplitudeMm[2] = 400.f;
    t.motion.periodS[2] = 5.f;
    s.objects[0] = t;
    s.numObjects = 1;
  } else if (n == "approach") {
    // 4.5 m -> 0.8 m in 5 s: the box grows ~5.6x.
    s.wallDepthMm = 5500.f;
    startAt(&t.motion, 150.f, 150.f, 4500.f);
    t.motion.velocityMmPerS[2] = -740.f;
    t.motion.amplitudeMm[0] = 120.f;
    t.motion.periodS[0] = 2.5f;
    s.objects[0] = t;
    s.numObjects = 1;
  } else if (n == "turn") {
    // The paper's Tank case: initialised side-on, then turning to face the camera. A
    // 400 x 120 x 200 mm box at 2 m yaws 90 degrees in 5 s (image width ~105 px -> ~35 px)
    // while drifting 300 mm to the right.
    SceneObject b = texturedBox(200.f, 60.f, 200.f,
                                {TextureKind::Patches, {60, 170, 90}, {150, 40, 120}, 303, 4.f});
    b.yawRateRadPerS = kPi / 2 / 5.f;
    startAt(&b.motion, -150.f, 250.f, 2000.f);
    b.motion.velocityMmPerS[0] = 60.f;
    s.objects[0] = b;
    s.numObjects = 1;
  } else if (n == "fast") {
    // 40 px a frame sideways at 2 m (fx 518: 4633 mm/s), turning every 12 frames at
    // 240 px either side of the image centre (frames 6, 18, 30, ...): every frame's step is
    // a full 40 px; a slow vertical sway besides.
    startAt(&t.motion, 0.f, 150.f, 2000.f);
    t.motion.triangleAmplitudeMm[0] = 240.f * 2000.f / 518.f;
    t.motion.trianglePeriodS[0] = 0.8f;
    t.motion.trianglePhase[0] = 0.25f;  // at the centre, moving right
    t.motion.amplitudeMm[1] = 40.f;
    t.motion.periodS[1] = 2.f;
    s.objects[0] = t;
    s.numObjects = 1;
  } else if (n == "lookalike") {
    // The target drifts left at 2.4 m; a same-textured cylinder (radius 65 mm, 220 mm tall:
    // ~1.2x the target's image size) at 1.6 m sweeps left -> right, its speed falling to 0
    // at t = 2.5 s, right over the target (x(t) = -1000 + 400 t + 318.3 sin(2 pi t / 5)).
    startAt(&t.motion, 100.f, 200.f, 2400.f);
    t.motion.velocityMmPerS[0] = -40.f;
    SceneObject look = t;
    look.radiusMm = 65.f;
    look.heightMm = 220.f;
    look.motion = MotionSpec{};
    startAt(&look.motion, -1000.f, 136.f, 1600.f);
    look.motion.velocityMmPerS[0] = 400.f;
    look.motion.amplitudeMm[0] = 400.f * 5.f / (2.f * kPi);
    look.motion.periodS[0] = 5.f;
    s.objects[0] = t;
    s.objects[1] = look;
    s.numObjects = 2;
  } else if (n == "leave-return") {
    // Out on the right at 700 mm/s; while out of view (frames kLeaveFirst..+29) it jumps to
    // just inside the left edge, 100 mm higher, and moves on right at 250 mm/s.
    startAt(&t.motion, 200.f, 200.f, 2000.f);
    t.motion.velocityMmPerS[0] = 700.f;
    t.motion.jumpAtS = kLeaveReturnJumpFrame / 30.f;
    t.motion.jumpMm[0] = kLeaveReturnJumpXMm;
    t.motion.jumpMm[1] = -100.f;
    t.motion.jumpVelocityMmPerS[0] = 250.f;
    s.objects[0] = t;
    s.numObjects = 1;
  } else if (n == "against-surface") {
    // A bag (200 x 80 x 260 mm box) at 1.8 m slides right at 120 mm/s along a board
    // (1400 x 60 x 800 mm) drifting right at 60 mm/s, whose front is 40 mm behind the bag's
    // back: the bag stands 120 mm out of its background in depth.
    SceneObject bag = texturedBox(
        100.f, 40.f, 260.f, {TextureKind::Patches, {40, 120, 180}, {220, 200, 170}, 405, 4.f});
    startAt(&bag.motion, -300.f, 250.f, 1800.f);
    bag.motion.velocityMmPerS[0] = 120.f;
    SceneObject board = texturedBox(700.f, 30.f, 800.f,
                                    {TextureKind::Patches, {120, 90, 60}, {70, 60, 50}, 404, 8.f});
    startAt(&board.motion, -150.f, 200.f, 1800.f + 40.f + 40.f + 30.f);
    board.motion.velocityMmPerS[0] = 60.f;
    s.objects[0] = bag;
    s.objects[1] = board;
    s.numObjects = 2;
  } else if (n == "held") {
    // The target carried around (x, y and z sways), a "hand" (140 x 50 x 120 mm box, skin
    // tones in finger-wide stripes) 115 mm in front of its centre over its lower right
    // half, sliding +-20 mm across it.
    carriedAround(&t.motion, 450.f);
    t.motion.phaseRad[2] = 1.f;
    SceneObject hand = texturedBox(
        70.f, 25.f, 120.f, {TextureKind::Stripes, {222, 170, 138}, {196, 142, 112}, 1, 2.5f});
    hand.motion = t.motion;
    hand.motion.startMm[0] += 76.f;
    hand.motion.startMm[1] += 40.f;
    hand.motion.startMm[2] -= 115.f;
    hand.motion.triangleAmplitudeMm[0] = 12.f;
    hand.motion.trianglePeriodS[0] = 2.5f;
    s.objects[0] = t;
    s.objects[1] = hand;
    s.numObjects = 2;
  } else if (n == "flat-turn") {
    // A 260 x 50 x 320 mm box (a book, a flat bag) at 2 m yaws 0.68 (1 - cos(2 pi t / 5))
    // rad: face-on -> 78 degrees at t = 2.5 s -> face-on, drifting right.
    SceneObject b = texturedBox(130.f, 25.f, 320.f,
                                {TextureKind::Patches, {30, 80, 160}, {230, 220, 200}, 606, 4.f});
    b.yawRad = 0.68f;
    b.yawAmplitudeRad = 0.68f;
    b.yawPeriodS = 5.f;
    b.yawPhaseRad = -kPi / 2;
    startAt(&b.motion, -200.f, 200.f, 2000.f);
    b.motion.velocityMmPerS[0] = 80.f;
    s.objects[0] = b;
    s.numObjects = 1;
  } else if (n == "edge-holes") {
    // Moving target (x and z sways) whose depth drops out along its silhouette.
    startAt(&t.motion, 0.f, 200.f, 2000.f);
    t.motion.amplitudeMm[0] = 500.f;
    t.motion.periodS[0] = 4.f;
    t.motion.amplitudeMm[2] = 300.f;
    t.motion.periodS[2] = 5.f;
    s.objects[0] = t;
    s.numObjects = 1;
    s.edgeHoleProbability = 0.6f;
    s.edgeHoleBandPx = 3;
  } else if (n == "no-depth") {
    // Moving target (x, y and z sways) that reads no depth for 70 frames, moving in depth
    // meanwhile: what colour alone must hold.
    carriedAround(&t.motion, 500.f);
    s.objects[0] = t;
    s.numObjects = 1;
    s.targetNoDepthFirst = 40;
    s.targetNoDepthLast = 109;
  } else {  // box
    SceneObject b = texturedBox(90.f, 60.f, 160.f,
                                {TextureKind::Patches, {230, 200, 40}, {40, 40, 40}, 202, 4.f});
    startAt(&b.motion, 0.f, 250.f, 2000.f);
    b.motion.amplitudeMm[0] = 700.f;
    b.motion.periodS[0] = 5.f;
    b.motion.amplitudeMm[2] = 500.f;
    b.motion.periodS[2] = 5.f;
    b.motion.phaseRad[2] = kPi / 2;
    s.objects[0] = b;
    s.numObjects = 1;
  }
  *out = s;
  return true;
}

SyntheticSource::SyntheticSource(const SceneSpec& spec, uint64_t seed) : _spec(spec), _seed(seed) {
  if (_spec.width < 8 || _spec.height < 8 || _spec.width > kMaxImageWidth ||
      _spec.height > kMaxImageHeight) {
    std::snprintf(_error, sizeof _error, "synth:%s: image size %dx%d outside 8x8..%dx%d",
                  _spec.name, _spec.width, _spec.height, kMaxImageWidth, kMaxImageHeight);
  } else if (_spec.numObjects < 1 || _spec.numObjects > kMaxSceneObjects || _spec.targetIndex < 0 ||
             _spec.targetIndex >= _spec.numObjects) {
    std::snprintf(_error, sizeof _error, "synth:%s: needs 1..%d objects and a valid target",
                  _spec.name, kMaxSceneObjects);
  } else if (!(_spec.fps > 0.f) || _spec.frameCount < 0) {
    std::snprintf(_error, sizeof _error, "synth:%s: fps must be > 0 and frames >= 0", _spec.name);
  }
  const float sx = static_cast<float>(_spec.width) / 640.f;
  const float sy = static_cast<float>(_spec.height) / 480.f;
  _k = {_spec.intrinsics.fx * sx, _spec.intrinsics.fy * sy, _spec.intrinsics.cx * sx,
        _spec.intrinsics.cy * sy};
  _invFx = 1.f / _k.fx;
  _invFy = 1.f / _k.fy;

  uint64_t s = seed ^ 0xC0FFEEull;
  for (int i = 0; i < 4096; i += 2) {
    // Box-Muller on two uniforms in (0, 1].
    const double u1 = (static_cast<double>(splitmix64(s) >> 11) + 1.0) / 9007199254740993.0;
    const double u2 = static_cast<double>(splitmix64(s) >> 11) / 9007199254740992.0;
    const double r = std::sqrt(-2.0 * std::log(u1));
    _gaussian[i] = static_cast<float>(r * std::cos(2.0 * 3.14159265358979 * u2));
    _gaussian[i + 1] = static_cast<float>(r * std::sin(2.0 * 3.14159265358979 * u2));
  }
  const uint32_t noiseAmp = static_cast<uint32_t>(_spec.colourNoise + 0.5f);
  for (int i = 0; i < kColourNoiseLen; ++i)
    _colourNoise[i] = static_cast<int8_t>(
        noiseAmp ? static_cast<int>(splitmix64(s) % (2 * noiseAmp + 1)) - static_cast<int>(noiseAmp)
                 : 0);
  makeTexture(_spec.wallTexture, _wallTexture);
  makeTexture(_spec.floorTexture, _floorTexture);
  for (int i = 0; i < kMaxSceneObjects; ++i)
    makeTexture(_spec.objects[i].texture, _objectTexture[i]);
}

void SyntheticSource::objectPosition(int i, float tS, float outMm[3]) const {
  const MotionSpec& m = _spec.objects[i].motion;
  const bool jumped = m.jumpAtS >= 0.f && tS >= m.jumpAtS;
  for (int a = 0; a < 3; ++a) {
    if (jumped) {
      outMm[a] = m.startMm[a] + m.velocityMmPerS[a] * m.jumpAtS + m.jumpMm[a] +
                 m.jumpVelocityMmPerS[a] * (tS - m.jumpAtS);
    } else {
      outMm[a] = m.startMm[a] + m.velocityMmPerS[a] * tS;
    }
    if (m.amplitudeMm[a] != 0.f && m.periodS[a] > 0.f)
      outMm[a] += m.amplitudeMm[a] * std::sin(2.f * kPi * tS / m.periodS[a] + m.phaseRad[a]);
    if (m.triangleAmplitudeMm[a] != 0.f && m.trianglePeriodS[a] > 0.f) {
      // tri(f) = 1 - 4 |frac(f) - 1/2|: no libm, the same bits everywhere.
      const float f = tS / m.trianglePeriodS[a] + m.trianglePhase[a];
      const float frac = f - static_cast<float>(floorToInt(f));
      const float d = frac - 0.5f;
      outMm[a] += m.triangleAmplitudeMm[a] * (1.f - 4.f * (d < 0.f ? -d : d));
    }
  }
}

float SyntheticSource::objectYaw(int i, float tS) const {
  const SceneObject& o = _spec.objects[i];
  float yaw = o.yawRad + o.yawRateRadPerS * tS;
  if (o.yawAmplitudeRad != 0.f && o.yawPeriodS > 0.f)
    yaw += o.yawAmplitudeRad * std::sin(2.f * kPi * tS / o.yawPeriodS + o.yawPhaseRad);
  return yaw;
}

ReadStatus SyntheticSource::next(FrameSlot& out) {
  if (_error[0]) return ReadStatus::Error;
  if (_next >= _spec.frameCount) return ReadStatus::End;
  if (!render(_next, out)) return ReadStatus::Error;
  ++_next;
  return ReadStatus::Ok;
}

bool SyntheticSource::render(int index, FrameSlot& out) {
  if (_error[0]) return false;
  const int w = _spec.width, h = _spec.height;
  out.rgb.resize(w, h);
  out.depthMm.resize(w, h);
  out.hasDepth = true;
  out.index = index;
  out.timeUs = static_cast<uint64_t>(static_cast<double>(index) * 1e6 / _spec.fps + 0.5);
  out.intrinsics = _k;
  const float tS = static_cast<float>(index) / _spec.fps;
  uint64_t fs = _seed * 0x100000001B3ull + static_cast<uint64_t>(index) + 1;
  const uint32_t frameSeed = static_cast<uint32_t>(splitmix64(fs));

  if (_backdropRgb)
    renderBackdrop(out);
  else
    renderBackground(out, frameSeed);

  // Painter's order (far first) plus a z-test, so intersecting objects are still right.
  Posed posed[kMaxSceneObjects];
  const int n = _spec.numObjects;
  for (int i = 0; i < n; ++i) {
    posed[i].index = i;
    objectPosition(i, tS, posed[i].c);
    const SceneObject& o = _spec.objects[i];
    const float yaw = objectYaw(i, tS);
    posed[i].yawed = o.shape == ShapeKind::Box && yaw != 0.f;
    posed[i].cosYaw = posed[i].yawed ? std::cos(yaw) : 1.f;
    posed[i].sinYaw = posed[i].yawed ? std::sin(yaw) : 0.f;
  }
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && posed[j].c[2] > posed[j - 1].c[2]; --j) {
      const Posed tmp = posed[j];
      posed[j] = posed[j - 1];
      posed[j - 1] = tmp;
    }
  _truth = SynthTruth{};
  for (int i = 0; i < n; ++i) renderObject(posed[i], out, posed[i].index == _spec.targetIndex);

  const SceneObject& tgt = _spec.objects[_spec.targetIndex];
  for (int i = 0; i < n; ++i) {
    if (posed[i].index != _spec.targetIndex) continue;
    for (int a = 0; a < 3; ++a) _truth.centreMm[a] = posed[i].c[a];
    _truth.projectedBox = projectObject(posed[i]);
  }
  _truth.radiusMm = tgt.radiusMm;
  _truth.heightMm = tgt.heightMm;
  if (tgt.shape == ShapeKind::Box) _truth.yawRad = objectYaw(_spec.targetIndex, tS);
  int visible = 0;
  const uint8_t target = static_cast<uint8_t>(_spec.targetIndex);
  for (int i = 0; i < w * h; ++i) visible += _owner[i] == target;
  _truth.visiblePixels = visible;

  applyDepthModel(out, frameSeed);
  if (_spec.edgeHoleProbability > 0.f) applyEdgeHoles(out, frameSeed);
  if (index >= _spec.targetNoDepthFirst && index <= _spec.targetNoDepthLast) {
    uint16_t* depth = out.depthMm.data();
    for (int i = 0; i < w * h; ++i)
      if (_owner[i] == target) depth[i] = 0;
  }

  out.hasGroundTruth = true;
  out.groundTruth = visible > 0 ? _truth.projectedBox : Box{};
  out.hasTruthMm = true;
  for (int a = 0; a < 3; ++a) out.truthCentreMm[a] = _truth.centreMm[a];
  return true;
}

namespace {
// One background span of a row at constant depth tMm: texture column advances linearly
// with u, in 16.16 fixed point (an arithmetic shift floors negatives too).
void fillSpan(Rgb8* rgb, float* z, uint8_t* own, int u0, int u1, float tMm, const Rgb8* texRow,
              float s0Texels, float dsTexels) {
  if (u1 <= u0) return;
  int64_t sf = static_cast<int64_t>(static_cast<double>(s0Texels + dsTexels * u0) * 65536.0);
  const int64_t dsf = static_cast<int64_t>(static_cast<double>(dsTexels) * 65536.0);
  for (int u = u0; u < u1; ++u, sf += dsf) {
    rgb[u] = texRow[static_cast<int>(sf >> 16) & (kTextureSize - 1)];
    z[u] = tMm;
    own[u] = kBackgroundOwner;
  }
}
}  // namespace

void SyntheticSource::renderBackground(FrameSlot& out, uint32_t /*frameSeed*/) {
  const int w = _spec.width, h = _spec.height;
  const float invWallTexel = 1.f / _spec.wallTexture.texelMm;
  const float invFloorTexel = 1.f / _spec.floorTexture.texelMm;
  Rgb8 opening[kTextureSize];  // the opening: one dark colour
  for (Rgb8& c : opening) c = {35, 35, 40};
  const float wallD = _spec.wallDepthMm;
  // The wall covers columns [uL, uR) of every row; the opening the rest.
  auto column = [&](float xMm) {
    const float u = _k.cx + _k.fx * xMm / wallD;
    return u < 0.f ? 0 : (u > static_cast<float>(w) ? w : static_cast<int>(std::ceil(u)));
  };
  const int uL = column(_spec.wallLeftMm);
  const int uR = column(_spec.wallRightMm);
  for (int v = 0; v < h; ++v) {
    const float dy = (static_cast<float>(v) - _k.cy) * _invFy;
    const float floorT = (_spec.floorYMm > 0.f && dy > 0.f) ? _spec.floorYMm / dy : 1e30f;
    Rgb8* rgb = out.rgb.data() + v * w;
    float* z = _zMm + v * w;
    uint8_t* own = _owner + v * w;
    const int starts[3] = {0, uL, uR};
    const int ends[3] = {uL, uR, w};
    for (int seg = 0; seg < 3; ++seg) {
      const bool wall = seg == 1;
      const float segT = wall ? wallD : _spec.openingDepthMm;
      if (floorT < segT) {
        const Rgb8* row = _floorTexture +
                          (floorToInt(floorT * invFloorTexel) & (kTextureSize - 1)) * kTextureSize;
        const float ds = floorT * _invFx * invFloorTexel;
        fillSpan(rgb, z, own, starts[seg], ends[seg], floorT, row, -_k.cx * ds, ds);
      } else if (wall) {
        const Rgb8* row =
            _wallTexture +
            (floorToInt(wallD * dy * invWallTexel) & (kTextureSize - 1)) * kTextureSize;
        const float ds = wallD * _invFx * invWallTexel;
        fillSpan(rgb, z, own, starts[seg], ends[seg], wallD, row, -_k.cx * ds, ds);
      } else {
        fillSpan(rgb, z, own, starts[seg], ends[seg], segT, opening, 0.f, 0.f);
      }
    }
  }
}

Box SyntheticSource::projectObject(const Posed& p) const {
  const SceneObject& o = _spec.objects[p.index];
  const float hh = o.heightMm * 0.5f;
  float u0 = 1e30f, v0 = 1e30f, u1 = -1e30f, v1 = -1e30f;
  auto add = [&](float x, float y, float z) {
    if (z < 1.f) z = 1.f;
    const float u = _k.cx + _k.fx * x / z, v = _k.cy + _k.fy * y / z;
    if (u < u0) u0 = u;
    if (u > u1) u1 = u;
    if (v < v0) v0 = v;
    if (v > v1) v1 = v;
  };
  if (o.shape == ShapeKind::Cylinder) {
    // Dense samples of both rims: the silhouette error is r (1 - cos(pi / 360)) < 0.01 px.
    for (int i = 0; i < 360; ++i) {
      const float a = static_cast<float>(i) * (2.f * kPi / 360.f);
      const float x = p.c[0] + o.radiusMm * std::sin(a), z = p.c[2] - o.radiusMm * std::cos(a);
      add(x, p.c[1] - hh, z);
      add(x, p.c[1] + hh, z);
    }
  } else if (!p.yawed) {
    for (int i = 0; i < 8; ++i)
      add(p.c[0] + ((i & 1) ? o.radiusMm : -o.radiusMm), p.c[1] + ((i & 2) ? hh : -hh),
          p.c[2] + ((i & 4) ? o.halfDepthMm : -o.halfDepthMm));
  } else {
    // The 8 corners of the yawed box: a convex body's silhouette is their hull.
    for (int i = 0; i < 8; ++i) {
      const float lx = (i & 1) ? o.radiusMm : -o.radiusMm;
      const float lz = (i & 4) ? o.halfDepthMm : -o.halfDepthMm;
      add(p.c[0] + p.cosYaw * lx - p.sinYaw * lz, p.c[1] + ((i & 2) ? hh : -hh),
          p.c[2] + p.sinYaw * lx + p.cosYaw * lz);
    }
  }
  const float W = static_cast<float>(_spec.width), H = static_cast<float>(_spec.height);
  if (u0 < 0.f) u0 = 0.f;
  if (v0 < 0.f) v0 = 0.f;
  if (u1 > W) u1 = W;
  if (v1 > H) v1 = H;
  if (u1 <= u0 || v1 <= v0) return Box{};
  return Box{u0, v0, u1 - u0, v1 - v0};
}

void SyntheticSource::renderObject(const Posed& p, FrameSlot& out, bool isTarget) {
  const SceneObject& o = _spec.objects[p.index];
  const float X = p.c[0], Y = p.c[1], Z = p.c[2];
  const float R = o.radiusMm, hh = o.heightMm * 0.5f;
  const float D = o.shape == ShapeKind::Cylinder ? R : o.halfDepthMm;
  // Nearest z of the object: a yawed box reaches |s| R + |c| D in front of its centre.
  const float frontMm = p.yawed ? std::fabs(p.sinYaw) * R + std::fabs(p.cosYaw) * o.halfDepthMm : D;
  if (Z - frontMm < 50.f) return;  // behind or touching the camera: not drawn
  const Box bb = projectObject(p);
  if (bb.empty()) return;
  const int w = _spec.width;
  const int ub = static_cast<int>(bb.x), vb = static_cast<int>(bb.y);
  int ue = static_cast<int>(std::ceil(bb.x + bb.w)), ve = static_cast<int>(std::ceil(bb.y + bb.h));
  if (ue > _spec.width) ue = _spec.width;
  if (ve > _spec.height) ve = _spec.height;
  const Rgb8* tex = _objectTexture[p.index];
  const float invTexel = 1.f / o.texture.texelMm;
  const float yTop = Y - hh, yBot = Y + hh;
  const uint8_t owner = static_cast<uint8_t>(p.index);
  // Yawed box: the camera (ray origin) in the box's frame, camera -> local being
  // lx = c x + s z, lz = -s x + c z.
  const float cw = p.cosYaw, sw = p.sinYaw;
  const float ox = -(cw * X + sw * Z), oz = -(-sw * X + cw * Z);
  int hits = 0;
  for (int v = vb; v < ve; ++v) {
    const float dy = (static_cast<float>(v) - _k.cy) * _invFy;
    for (int u = ub; u < ue; ++u) {
      const float dx = (static_cast<float>(u) - _k.cx) * _invFx;
      float t = -1.f, nx = 0.f, ny = 0.f, nz = -1.f, s = 0.f, q = 0.f;
      if (o.shape == ShapeKind::Cylinder) {
        const float A = dx * dx + 1.f, B = dx * X + Z, C = X * X + Z * Z - R * R;
        const float disc = B * B - A * C;
        if (disc < 0.f) continue;
        const float ts = (B - std::sqrt(disc)) / A;
        const float ys = ts * dy;
        if (ys >= yTop && ys <= yBot) {
          t = ts;
          nx = (ts * dx - X) / R;
          nz = (ts - Z) / R;
          ny = 0.f;
          s = R * std::atan2(nx, -nz);
          q = ys - yTop;
        } else {
          // The cap facing the camera (top when the camera looks down on it).
          const float yc = yTop > 0.f ? yTop : (yBot < 0.f ? yBot : 0.f);
          if (yc == 0.f || dy == 0.f) continue;
          const float tc = yc / dy;
          if (tc <= 0.f) continue;
          const float ex = tc * dx - X, ez = tc - Z;
          if (ex * ex + ez * ez > R * R) continue;
          t = tc;
          nx = 0.f;
          nz = 0.f;
          ny = yc == yTop ? -1.f : 1.f;
          s = ex;
          q = ez;
        }
      } else if (p.yawed) {
        // Slabs in the box's frame (the ray parameter is still camera depth); the
        // entry face is the one with the largest near distance.
        const float lx = cw * dx + sw, lz = -sw * dx + cw;  // ray direction, local
        float tn = -1e30f, tf = 1e30f;
        int face = 2;
        auto slab = [&](float o0, float d, float half, int f) {
          if (d == 0.f) return o0 >= -half && o0 <= half;
          clipSlab((-half - o0) / d, (half - o0) / d, f, &tn, &tf, &face);
          return true;
        };
        if (!slab(oz, lz, D, 2) || !slab(ox, lx, R, 0)) continue;
        if (dy != 0.f) {
          clipSlab(yTop / dy, yBot / dy, 1, &tn, &tf, &face);
        } else if (yTop > 0.f || yBot < 0.f) {
          continue;
        }
        if (tn > tf || tn <= 0.f) continue;
        t = tn;
        const float hx = ox + t * lx, hz = oz + t * lz, py = t * dy;  // hit point, local
        float nlx = 0.f, nlz = 0.f;
        if (face == 0) {
          nlx = lx > 0.f ? -1.f : 1.f;
          s = hz + D;
          q = py - yTop;
        } else if (face == 1) {
          ny = dy > 0.f ? -1.f : 1.f;
          s = hx + R;
          q = hz + D;
        } else {
          nlz = lz > 0.f ? -1.f : 1.f;
          s = hx + R;
          q = py - yTop;
        }
        nx = cw * nlx - sw * nlz;  // the normal back in camera coordinates
        nz = sw * nlx + cw * nlz;
      } else {
        // Slabs; the entry face is the one with the largest near distance.
        float tn = Z - D, tf = Z + D;
        int face = 2;
        if (dx != 0.f) {
          clipSlab((X - R) / dx, (X + R) / dx, 0, &tn, &tf, &face);
        } else if (X - R > 0.f || X + R < 0.f) {
          continue;
        }
        if (dy != 0.f) {
          clipSlab(yTop / dy, yBot / dy, 1, &tn, &tf, &face);
        } else if (yTop > 0.f || yBot < 0.f) {
          continue;
        }
        if (tn > tf || tn <= 0.f) continue;
        t = tn;
        const float px = t * dx, py = t * dy, pz = t;
        if (face == 0) {
          nx = dx > 0.f ? -1.f : 1.f;
          nz = 0.f;
          s = pz - (Z - D);
          q = py - yTop;
        } else if (face == 1) {
          ny = dy > 0.f ? -1.f : 1.f;
          nz = 0.f;
          s = px - (X - R);
          q = pz - (Z - D);
        } else {
          s = px - (X - R);
          q = py - yTop;
        }
      }
      ++hits;
      const int i = v * w + u;
      if (t >= _zMm[i]) continue;
      _zMm[i] = t;
      _owner[i] = owner;
      const Rgb8 c = sample(tex, s, q, invTexel);
      out.rgb.data()[i] = o.shaded ? shade(c, nx, ny, nz) : c;
    }
  }
  if (isTarget) _truth.projectedPixels = hits;
}

void SyntheticSource::applyDepthModel(FrameSlot& out, uint32_t frameSeed) {
  const int w = _spec.width, h = _spec.height;
  // Brightness for this frame, in 1/256 steps.
  const float tS = static_cast<float>(out.index) / _spec.fps;
  float gain = 1.f;
  if (_spec.lightAmplitude != 0.f && _spec.lightPeriodS > 0.f)
    gain += _spec.lightAmplitude * std::sin(2.f * kPi * tS / _spec.lightPeriodS);
  if (_spec.lightStepFrame >= 0 && out.index >= _spec.lightStepFrame) gain *= _spec.lightStepGain;
  if (gain < 0.f) gain = 0.f;
  const int gain256 = static_cast<int>(gain * 256.f + 0.5f);
  const float fb = _k.fx * _spec.baselineMm;
  const float sigma = _spec.disparityNoiseRaw;
  const float minZ = _spec.minDepthMm, maxZ = _spec.maxDepthMm;
  const bool shadows = _spec.shadows;
  constexpr float kB = static_cast<float>(kinect::kRawToInvMetresB);
  constexpr float kInvA = static_cast<float>(1.0 / kinect::kRawToInvMetresA);
  constexpr float kNoDepthF = static_cast<float>(kinect::kRawNoDepth);

  for (int v = 0; v < h; ++v) {
    // Noise comes from fixed tables at a random offset per row: one draw per row keeps
    // the per-pixel loops branch-light (colour) and division-free on background runs.
    uint64_t rs = (static_cast<uint64_t>(frameSeed) << 32) ^
                  ((static_cast<uint64_t>(v) + 1) * 0x9E3779B97F4A7C15ull);
    const uint64_t rowDraw = splitmix64(rs);
    const int8_t* cn = _colourNoise + (rowDraw & (kColourNoiseLen / 2 - 1));
    const float* gn = _gaussian + ((rowDraw >> 32) & 2047u);
    Rgb8* rgb = out.rgb.data() + v * w;
    uint8_t* bytes = reinterpret_cast<uint8_t*>(rgb);
    if (gain256 == 256) {
      // Noise only (most scenes): 16-bit lanes, no multiply.
      for (int i = 0; i < 3 * w; ++i) {
        const int16_t val = static_cast<int16_t>(bytes[i] + cn[i]);
        bytes[i] = static_cast<uint8_t>(val < 0 ? 0 : (val > 255 ? 255 : val));
      }
    } else {
      // Gain in 1/128 steps, at most 2x, so the product fits 16-bit lanes (255 * 256).
      const uint16_t g128 = static_cast<uint16_t>(gain256 >= 512 ? 256 : (gain256 + 1) / 2);
      for (int i = 0; i < 3 * w; ++i) {
        const uint16_t scaled = static_cast<uint16_t>((bytes[i] * g128 + 64u) >> 7);
        const int16_t val = static_cast<int16_t>(scaled + cn[i]);
        bytes[i] = static_cast<uint8_t>(val < 0 ? 0 : (val > 255 ? 255 : val));
      }
    }
    uint16_t* dmm = out.depthMm.data() + v * w;
    const float* z = _zMm + v * w;
    // Pass 1 (vectorised: restrict pointers, float clamps, int32 out): true depth ->
    // noisy raw disparity (1/8 px steps); out of range -> "no reading".
    {
      const float* __restrict zr = z;
      const float* __restrict g = gn;
      float* __restrict inv = _rowInvZ;
      int32_t* __restrict rawOut = _rowRaw;
      for (int u = 0; u < w; ++u) {
        const float zz = zr[u];
        const float iv = 1.f / zz;
        inv[u] = iv;
        float raw = (1000.f * iv - kB) * kInvA + sigma * g[u] + 0.5f;
        raw = raw < 0.f ? 0.f : raw;
        raw = raw > kNoDepthF ? kNoDepthF : raw;
        const int32_t q = static_cast<int32_t>(raw);
        rawOut[u] = (zz >= minZ && zz <= maxZ) ? q : kinect::kRawNoDepth;
      }
    }
    if (_backdropDepthMm) {
      backdropDepthRow(v, dmm);
      continue;
    }
    // Pass 2, right to left: a pixel is in the projector's shadow when a nearer pixel to
    // its right lands at or left of it in the projector's image.
    float runMin = 1e30f;
    for (int u = w - 1; u >= 0; --u) {
      const float up = static_cast<float>(u) - fb * _rowInvZ[u];  // column in the projector image
      const bool shadowed = shadows && up > runMin;
      runMin = up < runMin ? up : runMin;
      dmm[u] = shadowed ? 0 : _rawToMm.mm[_rowRaw[u]];
    }
  }
}

void SyntheticSource::setBackdrop(const Rgb8* rgb, const uint16_t* depthMm,
                                  const CameraIntrinsics& k) {
  _backdropRgb = rgb;
  _backdropDepthMm = depthMm;
  _k = k;
  _invFx = 1.f / _k.fx;
  _invFy = 1.f / _k.fy;
}

void SyntheticSource::renderBackdrop(FrameSlot& out) {
  const int n = _spec.width * _spec.height;
  std::memcpy(static_cast<void*>(out.rgb.data()), _backdropRgb, sizeof(Rgb8) * n);
  for (int i = 0; i < n; ++i) {
    // A hole is no surface: it hides nothing behind it.
    const uint16_t d = _backdropDepthMm[i];
    _zMm[i] = d ? static_cast<float>(d) : kHoleZMm;
    _owner[i] = kBackgroundOwner;
  }
}

// The depth model's pass 2 over a still (pass 1 made _rowInvZ and _rowRaw): the still's
// pixels keep their real reading, which already has its own noise and shadows, unless an
// object's pixel casts the projector's shadow on them; an object's pixel is shadowed by
// anything nearer to its right, object or real surface.
void SyntheticSource::backdropDepthRow(int v, uint16_t* dmm) {
  const int w = _spec.width;
  const float fb = _k.fx * _spec.baselineMm;
  const uint16_t* still = _backdropDepthMm + v * w;
  const uint8_t* own = _owner + v * w;
  float runMinAll = 1e30f, runMinObjects = 1e30f;
  for (int u = w - 1; u >= 0; --u) {
    const float up = static_cast<float>(u) - fb * _rowInvZ[u];  // column in the projector image
    const bool object = own[u] != kBackgroundOwner;
    if (object) {
      dmm[u] = _spec.shadows && up > runMinAll ? 0 : _rawToMm.mm[_rowRaw[u]];
      runMinObjects = up < runMinObjects ? up : runMinObjects;
    } else {
      dmm[u] = _spec.shadows && up > runMinObjects ? 0 : still[u];
    }
    runMinAll = up < runMinAll ? up : runMinAll;
  }
}

void SyntheticSource::applyEdgeHoles(FrameSlot& out, uint32_t frameSeed) {
  // Only pixels within the band of the target's projected box can be near its silhouette.
  const Box& b = _truth.projectedBox;
  if (b.empty() || _truth.projectedPixels == 0) return;
  const int w = _spec.width, h = _spec.height;
  const int band =
      _spec.edgeHoleBandPx < 1 ? 1 : (_spec.edgeHoleBandPx > 8 ? 8 : _spec.edgeHoleBandPx);
  const uint8_t target = static_cast<uint8_t>(_spec.targetIndex);
  int u0 = static_cast<int>(b.x) - band, v0 = static_cast<int>(b.y) - band;
  int u1 = static_cast<int>(std::ceil(b.x + b.w)) + band;
  int v1 = static_cast<int>(std::ceil(b.y + b.h)) + band;
  u0 = u0 < 0 ? 0 : u0;
  v0 = v0 < 0 ? 0 : v0;
  u1 = u1 > w ? w : u1;
  v1 = v1 > h ? h : v1;
  // Drop thresholds per distance, in 1/2^24 steps.
  uint32_t threshold[9] = {};
  for (int d = 1; d <= band; ++d)
    threshold[d] =
        static_cast<uint32_t>(_spec.edgeHoleProbability * static_cast<float>(band + 1 - d) /
                              static_cast<float>(band) * 16777216.f);
  uint16_t* depth = out.depthMm.data();
  for (int v = v0; v < v1; ++v) {
    for (int u = u0; u < u1; ++u) {
      const bool inside = _owner[v * w + u] == target;
      // Chebyshev distance to the other side of the silhouette: the first ring reaching it.
      int dist = 0;
      for (int r = 1; r <= band && dist == 0; ++r) {
        for (int dv = -r; dv <= r && dist == 0; ++dv) {
          const int vv = v + dv;
          if (vv < 0 || vv >= h) continue;
          const int step = (dv == -r || dv == r) ? 1 : 2 * r;
          for (int du = -r; du <= r; du += step) {
            const int uu = u + du;
            if (uu < 0 || uu >= w) continue;
            if ((_owner[vv * w + uu] == target) != inside) {
              dist = r;
              break;
            }
          }
        }
      }
      if (dist == 0) continue;
      uint64_t s = (static_cast<uint64_t>(frameSeed) << 32) ^
                   (static_cast<uint64_t>(v * w + u) * 0xD1B54A32D192ED03ull);
      if (static_cast<uint32_t>(splitmix64(s) >> 40) < threshold[dist]) depth[v * w + u] = 0;
    }
  }
}

}  // namespace cuetrack
