// A synthetic scene's frames: the objects posed at each frame's time, drawn by the
// rasteriser (SceneRaster.cpp) in painter's order, turned into a Kinect reading by the
// depth model (KinectDepthModel.cpp), with the exact truth of the target.
#include "cuetrack/drivers/SyntheticSource.hpp"

#include <cmath>
#include <cstdio>

#include "SynthCommon.hpp"

namespace cuetrack {

using synth::floorToInt;
using synth::kPi;
using synth::makeTexture;
using synth::splitmix64;

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
  synth::motionPosition(_spec.objects[i].motion, tS, outMm);
}

void synth::motionPosition(const MotionSpec& m, float tS, float outMm[3]) {
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
    posed[i].yawRad = yaw;
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

void SyntheticSource::setObjectTexture(int i, const Rgb8* tile) {
  if (i < 0 || i >= kMaxSceneObjects || !tile) return;
  for (int t = 0; t < kTextureSize * kTextureSize; ++t) _objectTexture[i][t] = tile[t];
}

void SyntheticSource::setBackdrop(const Rgb8* rgb, const uint16_t* depthMm,
                                  const CameraIntrinsics& k) {
  _backdropRgb = rgb;
  _backdropDepthMm = depthMm;
  _k = k;
  _invFx = 1.f / _k.fx;
  _invFy = 1.f / _k.fy;
}

}  // namespace cuetrack
