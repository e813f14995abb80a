// The scene catalogue: one row per scene, {name, summary, builder}. A builder starts
// from SceneSpec's defaults (640x480, 150 frames at 30 fps, the textured wall and floor)
// and adds its objects; makeScene looks a name up here and nowhere else.
#include "cuetrack/drivers/SceneCatalogue.hpp"

#include <cstdio>
#include <cstring>

#include "SynthCommon.hpp"

namespace cuetrack {

namespace {

using synth::kPi;

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

// The builders, one per row of kScenes below; most move the textured cylinder.

void moving(SceneSpec& s) {
  SceneObject t = texturedCylinder();
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
}

void twinCrossing(SceneSpec& s) {
  // Target left -> right at 1.8 m; its twin right -> left at 2.5 m; both at x = 0 at t = 2.5 s.
  SceneObject t = texturedCylinder();
  startAt(&t.motion, -900.f, 200.f, 1800.f);
  t.motion.velocityMmPerS[0] = 360.f;
  SceneObject twin = t;
  startAt(&twin.motion, 1100.f, 250.f, 2500.f);
  twin.motion.velocityMmPerS[0] = -440.f;
  s.objects[0] = t;
  s.objects[1] = twin;
  s.numObjects = 2;
}

void occlusion(SceneSpec& s) {
  // A wide striped box at 1.2 m sweeps across and hides the target completely mid-way.
  SceneObject t = texturedCylinder();
  startAt(&t.motion, -200.f, 200.f, 2200.f);
  t.motion.velocityMmPerS[0] = 80.f;
  SceneObject occ = texturedBox(220.f, 50.f, 600.f,
                                {TextureKind::Stripes, {60, 160, 60}, {230, 230, 80}, 7, 6.f});
  startAt(&occ.motion, -1300.f, 110.f, 1200.f);
  occ.motion.velocityMmPerS[0] = 500.f;
  s.objects[0] = t;
  s.objects[1] = occ;
  s.numObjects = 2;
}

void untextured(SceneSpec& s) {
  SceneObject t = texturedCylinder();
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
}

void lighting(SceneSpec& s) {
  moving(s);
  s.lightAmplitude = 0.35f;
  s.lightPeriodS = 3.f;
  s.lightStepFrame = 75;
  s.lightStepGain = 0.55f;
}

void approach(SceneSpec& s) {
  // 4.5 m -> 0.8 m in 5 s: the box grows ~5.6x.
  SceneObject t = texturedCylinder();
  s.wallDepthMm = 5500.f;
  startAt(&t.motion, 150.f, 150.f, 4500.f);
  t.motion.velocityMmPerS[2] = -740.f;
  t.motion.amplitudeMm[0] = 120.f;
  t.motion.periodS[0] = 2.5f;
  s.objects[0] = t;
  s.numObjects = 1;
}

void box(SceneSpec& s) {
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

void turn(SceneSpec& s) {
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
}

void fast(SceneSpec& s) {
  // 40 px a frame sideways at 2 m (fx 518: 4633 mm/s), turning every 12 frames at
  // 240 px either side of the image centre (frames 6, 18, 30, ...): every frame's step is
  // a full 40 px; a slow vertical sway besides.
  SceneObject t = texturedCylinder();
  startAt(&t.motion, 0.f, 150.f, 2000.f);
  t.motion.triangleAmplitudeMm[0] = 240.f * 2000.f / 518.f;
  t.motion.trianglePeriodS[0] = 0.8f;
  t.motion.trianglePhase[0] = 0.25f;  // at the centre, moving right
  t.motion.amplitudeMm[1] = 40.f;
  t.motion.periodS[1] = 2.f;
  s.objects[0] = t;
  s.numObjects = 1;
}

void lookalike(SceneSpec& s) {
  // The target drifts left at 2.4 m; a same-textured cylinder (radius 65 mm, 220 mm tall:
  // ~1.2x the target's image size) at 1.6 m sweeps left -> right, its speed falling to 0
  // at t = 2.5 s, right over the target (x(t) = -1000 + 400 t + 318.3 sin(2 pi t / 5)).
  SceneObject t = texturedCylinder();
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
}

void leaveReturn(SceneSpec& s) {
  // Out on the right at 700 mm/s; while out of view (frames kLeaveFirst..+29) it jumps to
  // just inside the left edge, 100 mm higher, and moves on right at 250 mm/s.
  SceneObject t = texturedCylinder();
  startAt(&t.motion, 200.f, 200.f, 2000.f);
  t.motion.velocityMmPerS[0] = 700.f;
  t.motion.jumpAtS = kLeaveReturnJumpFrame / 30.f;
  t.motion.jumpMm[0] = kLeaveReturnJumpXMm;
  t.motion.jumpMm[1] = -100.f;
  t.motion.jumpVelocityMmPerS[0] = 250.f;
  s.objects[0] = t;
  s.numObjects = 1;
}

void againstSurface(SceneSpec& s) {
  // A bag (200 x 80 x 260 mm box) at 1.8 m slides right at 120 mm/s along a board
  // (1400 x 60 x 800 mm) drifting right at 60 mm/s, whose front is 40 mm behind the bag's
  // back: the bag stands 120 mm out of its background in depth.
  SceneObject bag = texturedBox(100.f, 40.f, 260.f,
                                {TextureKind::Patches, {40, 120, 180}, {220, 200, 170}, 405, 4.f});
  startAt(&bag.motion, -300.f, 250.f, 1800.f);
  bag.motion.velocityMmPerS[0] = 120.f;
  SceneObject board = texturedBox(700.f, 30.f, 800.f,
                                  {TextureKind::Patches, {120, 90, 60}, {70, 60, 50}, 404, 8.f});
  startAt(&board.motion, -150.f, 200.f, 1800.f + 40.f + 40.f + 30.f);
  board.motion.velocityMmPerS[0] = 60.f;
  s.objects[0] = bag;
  s.objects[1] = board;
  s.numObjects = 2;
}

void held(SceneSpec& s) {
  // The target carried around (x, y and z sways), a "hand" (140 x 50 x 120 mm box, skin
  // tones in finger-wide stripes) 115 mm in front of its centre over its lower right
  // half, sliding +-20 mm across it.
  SceneObject t = texturedCylinder();
  carriedAround(&t.motion, 450.f);
  t.motion.phaseRad[2] = 1.f;
  SceneObject hand = texturedBox(70.f, 25.f, 120.f,
                                 {TextureKind::Stripes, {222, 170, 138}, {196, 142, 112}, 1, 2.5f});
  hand.motion = t.motion;
  hand.motion.startMm[0] += 76.f;
  hand.motion.startMm[1] += 40.f;
  hand.motion.startMm[2] -= 115.f;
  hand.motion.triangleAmplitudeMm[0] = 12.f;
  hand.motion.trianglePeriodS[0] = 2.5f;
  s.objects[0] = t;
  s.objects[1] = hand;
  s.numObjects = 2;
}

void flatTurn(SceneSpec& s) {
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
}

void edgeHoles(SceneSpec& s) {
  // Moving target (x and z sways) whose depth drops out along its silhouette.
  SceneObject t = texturedCylinder();
  startAt(&t.motion, 0.f, 200.f, 2000.f);
  t.motion.amplitudeMm[0] = 500.f;
  t.motion.periodS[0] = 4.f;
  t.motion.amplitudeMm[2] = 300.f;
  t.motion.periodS[2] = 5.f;
  s.objects[0] = t;
  s.numObjects = 1;
  s.edgeHoleProbability = 0.6f;
  s.edgeHoleBandPx = 3;
}

void noDepth(SceneSpec& s) {
  // Moving target (x, y and z sways) that reads no depth for 70 frames, moving in depth
  // meanwhile: what colour alone must hold.
  SceneObject t = texturedCylinder();
  carriedAround(&t.motion, 500.f);
  s.objects[0] = t;
  s.numObjects = 1;
  s.targetNoDepthFirst = 40;
  s.targetNoDepthLast = 109;
}

constexpr SceneEntry kScenes[] = {
    {"moving", "textured cylinder moving in x, y and z before a textured background", moving},
    {"twin-crossing", "target and a same-textured twin crossing it 700 mm further back",
     twinCrossing},
    {"occlusion", "a box passes in front of the target, hiding it completely for a while",
     occlusion},
    {"untextured", "grey cylinder on a grey wall and floor of the same grey: only depth sees it",
     untextured},
    {"lighting", "moving target under slow brightness change plus a step (lights dimmed)",
     lighting},
    {"approach", "target comes from 4.5 m to 0.8 m: strong perspective scale change", approach},
    {"box", "a textured box moving (shape variety)", box},
    {"turn", "an elongated box turns 90 degrees from side-on to end-on: image width ~1/3", turn},
    {"fast", "target sweeping sideways at 40 px a frame, turning at the image's sides", fast},
    {"lookalike", "a nearer same-textured cylinder pauses over the target: hidden in 65-85",
     lookalike},
    {"leave-return", "target out of view in frames 48-77, back from the left edge higher up",
     leaveReturn},
    {"against-surface", "a bag slides along a board 40 mm behind it: little depth contrast",
     againstSurface},
    {"held", "target carried with a skin-coloured \"hand\" in front hiding 14-35 % of it", held},
    {"flat-turn", "a flat box (a book) turns from face-on to 78 degrees and back: width ~2.6x",
     flatTurn},
    {"edge-holes", "moving target whose depth drops out on a 3 px band along its silhouette",
     edgeHoles},
    {"no-depth", "moving target whose surface reads no depth in frames 40-109: colour alone",
     noDepth},
};
constexpr int kNumScenes = static_cast<int>(sizeof(kScenes) / sizeof(kScenes[0]));

}  // namespace

int sceneCount() {
  return kNumScenes;
}

const SceneEntry* sceneEntry(int i) {
  return (i >= 0 && i < kNumScenes) ? &kScenes[i] : nullptr;
}

const char* sceneName(int i) {
  return (i >= 0 && i < kNumScenes) ? kScenes[i].name : nullptr;
}

bool makeScene(const char* name, SceneSpec* out) {
  if (!name || !out) return false;
  for (const SceneEntry& e : kScenes) {
    if (std::strcmp(name, e.name) != 0) continue;
    SceneSpec s;
    std::snprintf(s.name, sizeof s.name, "%s", e.name);
    e.build(s);
    *out = s;
    return true;
  }
  return false;
}

bool makeScene(const char* name, SceneSpec* out, char* err, size_t errLen) {
  if (makeScene(name, out)) return true;
  char names[512];
  listSceneNames(", ", names, sizeof names);
  std::snprintf(err, errLen, "unknown scene '%s' (scenes: %s)", name ? name : "", names);
  return false;
}

bool knownSceneSource(const char* spec, char* err, size_t errLen) {
  if (spec == nullptr) return true;
  const char* at = nullptr;
  size_t len = 0;
  if (std::strncmp(spec, "synth:", 6) == 0) {
    at = spec + 6;
    len = std::strcspn(at, ":");
  } else if (std::strncmp(spec, "still:", 6) == 0 && std::strchr(spec + 6, ':')) {
    at = std::strchr(spec + 6, ':') + 1;  // still:RGB,DEPTH,...:SCENE@PLACE
    len = std::strcspn(at, "@");
  } else {
    return true;
  }
  char name[64];
  std::snprintf(name, sizeof name, "%.*s", static_cast<int>(len), at);
  static SceneSpec scratch;  // large: not on the stack
  char why[600];
  if (makeScene(name, &scratch, why, sizeof why)) return true;
  std::snprintf(err, errLen, "%s: %s", spec, why);
  return false;
}

void listSceneNames(const char* separator, char* out, size_t len) {
  if (len == 0) return;
  out[0] = '\0';
  size_t used = 0;
  for (int i = 0; i < kNumScenes && used < len; ++i) {
    const int n =
        std::snprintf(out + used, len - used, "%s%s", i ? separator : "", kScenes[i].name);
    if (n < 0) return;
    used += static_cast<size_t>(n);
  }
}

}  // namespace cuetrack
