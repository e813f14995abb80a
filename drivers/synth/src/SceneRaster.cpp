// The rasteriser: ray casting of a few convex objects per frame. Only each object's
// projected bounding box is visited and the background is analytic (wall, floor,
// opening), so a 640x480 frame costs about one pass of arithmetic per pixel. Writes
// colour, the true depth (_zMm) and which object each pixel shows (_owner); the Kinect
// depth model (KinectDepthModel.cpp) turns the true depth into a reading.
#include <cmath>
#include <cstring>

#include "SynthCommon.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

namespace cuetrack {

using synth::floorToInt;
using synth::kBackgroundOwner;
using synth::kHoleZMm;
using synth::kPi;

namespace {

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

// One object as the rays see it, in camera coordinates.
struct RayObject {
  float X, Y, Z, R, D, yTop, yBot;
  float yawRad;          // a spinning cylinder's texture turn
  float cw, sw, ox, oz;  // a yawed box: its yaw and the camera in its frame
};

// Where a ray (dx, dy, 1) first meets the object: depth t, the surface normal and the
// texture coordinates (s, q) in mm.
struct RayHit {
  float t = -1.f, nx = 0.f, ny = 0.f, nz = -1.f, s = 0.f, q = 0.f;
};

bool hitCylinder(const RayObject& o, float dx, float dy, RayHit* h) {
  const float X = o.X, Z = o.Z, R = o.R, yTop = o.yTop, yBot = o.yBot;
  const float A = dx * dx + 1.f, B = dx * X + Z, C = X * X + Z * Z - R * R;
  const float disc = B * B - A * C;
  if (disc < 0.f) return false;
  const float ts = (B - std::sqrt(disc)) / A;
  const float ys = ts * dy;
  if (ys >= yTop && ys <= yBot) {
    h->t = ts;
    h->nx = (ts * dx - X) / R;
    h->nz = (ts - Z) / R;
    h->ny = 0.f;
    // A spinning cylinder turns its texture with it (yawRad 0: as ever).
    h->s = R * (o.yawRad != 0.f ? std::atan2(h->nx, -h->nz) - o.yawRad : std::atan2(h->nx, -h->nz));
    h->q = ys - yTop;
    return true;
  }
  // The cap facing the camera (top when the camera looks down on it).
  const float yc = yTop > 0.f ? yTop : (yBot < 0.f ? yBot : 0.f);
  if (yc == 0.f || dy == 0.f) return false;
  const float tc = yc / dy;
  if (tc <= 0.f) return false;
  const float ex = tc * dx - X, ez = tc - Z;
  if (ex * ex + ez * ez > R * R) return false;
  h->t = tc;
  h->nx = 0.f;
  h->nz = 0.f;
  h->ny = yc == yTop ? -1.f : 1.f;
  h->s = ex;
  h->q = ez;
  return true;
}

// Slabs in the box's frame (the ray parameter is still camera depth); the entry face is
// the one with the largest near distance.
bool hitYawedBox(const RayObject& o, float dx, float dy, RayHit* h) {
  const float R = o.R, D = o.D, yTop = o.yTop, yBot = o.yBot, cw = o.cw, sw = o.sw;
  const float lx = cw * dx + sw, lz = -sw * dx + cw;  // ray direction, local
  float tn = -1e30f, tf = 1e30f;
  int face = 2;
  auto slab = [&](float o0, float d, float half, int f) {
    if (d == 0.f) return o0 >= -half && o0 <= half;
    clipSlab((-half - o0) / d, (half - o0) / d, f, &tn, &tf, &face);
    return true;
  };
  if (!slab(o.oz, lz, D, 2) || !slab(o.ox, lx, R, 0)) return false;
  if (dy != 0.f) {
    clipSlab(yTop / dy, yBot / dy, 1, &tn, &tf, &face);
  } else if (yTop > 0.f || yBot < 0.f) {
    return false;
  }
  if (tn > tf || tn <= 0.f) return false;
  const float t = tn;
  h->t = t;
  const float hx = o.ox + t * lx, hz = o.oz + t * lz, py = t * dy;  // hit point, local
  float nlx = 0.f, nlz = 0.f;
  if (face == 0) {
    nlx = lx > 0.f ? -1.f : 1.f;
    h->s = hz + D;
    h->q = py - yTop;
  } else if (face == 1) {
    h->ny = dy > 0.f ? -1.f : 1.f;
    h->s = hx + R;
    h->q = hz + D;
  } else {
    nlz = lz > 0.f ? -1.f : 1.f;
    h->s = hx + R;
    h->q = py - yTop;
  }
  h->nx = cw * nlx - sw * nlz;  // the normal back in camera coordinates
  h->nz = sw * nlx + cw * nlz;
  return true;
}

// Slabs; the entry face is the one with the largest near distance.
bool hitBox(const RayObject& o, float dx, float dy, RayHit* h) {
  const float X = o.X, Z = o.Z, R = o.R, D = o.D, yTop = o.yTop, yBot = o.yBot;
  float tn = Z - D, tf = Z + D;
  int face = 2;
  if (dx != 0.f) {
    clipSlab((X - R) / dx, (X + R) / dx, 0, &tn, &tf, &face);
  } else if (X - R > 0.f || X + R < 0.f) {
    return false;
  }
  if (dy != 0.f) {
    clipSlab(yTop / dy, yBot / dy, 1, &tn, &tf, &face);
  } else if (yTop > 0.f || yBot < 0.f) {
    return false;
  }
  if (tn > tf || tn <= 0.f) return false;
  const float t = tn;
  h->t = t;
  const float px = t * dx, py = t * dy, pz = t;
  if (face == 0) {
    h->nx = dx > 0.f ? -1.f : 1.f;
    h->nz = 0.f;
    h->s = pz - (Z - D);
    h->q = py - yTop;
  } else if (face == 1) {
    h->ny = dy > 0.f ? -1.f : 1.f;
    h->nz = 0.f;
    h->s = px - (X - R);
    h->q = pz - (Z - D);
  } else {
    h->s = px - (X - R);
    h->q = py - yTop;
  }
  return true;
}

}  // namespace

namespace synth {

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

}  // namespace synth

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
  const uint8_t owner = static_cast<uint8_t>(p.index);
  // Yawed box: the camera (ray origin) in the box's frame, camera -> local being
  // lx = c x + s z, lz = -s x + c z.
  const float cw = p.cosYaw, sw = p.sinYaw;
  const RayObject ray{
      X, Y, Z, R, D, Y - hh, Y + hh, p.yawRad, cw, sw, -(cw * X + sw * Z), -(-sw * X + cw * Z)};
  const bool cylinder = o.shape == ShapeKind::Cylinder;
  int hits = 0;
  for (int v = vb; v < ve; ++v) {
    const float dy = (static_cast<float>(v) - _k.cy) * _invFy;
    for (int u = ub; u < ue; ++u) {
      const float dx = (static_cast<float>(u) - _k.cx) * _invFx;
      RayHit h;
      const bool seen = cylinder  ? hitCylinder(ray, dx, dy, &h)
                        : p.yawed ? hitYawedBox(ray, dx, dy, &h)
                                  : hitBox(ray, dx, dy, &h);
      if (!seen) continue;
      ++hits;
      const int i = v * w + u;
      if (h.t >= _zMm[i]) continue;
      _zMm[i] = h.t;
      _owner[i] = owner;
      const Rgb8 c = sample(tex, h.s, h.q, invTexel);
      out.rgb.data()[i] = o.shaded ? shade(c, h.nx, h.ny, h.nz) : c;
    }
  }
  if (isTarget) _truth.projectedPixels = hits;
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

}  // namespace cuetrack
