#include "cuetrack/core/cues/CylinderSizer.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/cues/SizeMeasure.hpp"

namespace cuetrack {

namespace {
// The silhouette is the depth within surface +- (D/2 + m) (a face seen obliquely reaches
// in front of the centre's depth as well as behind it), with m = this x the surface depth
// (Kinect depth noise grows with depth); per frame D and H move at most kMaxSizeStep
// (ln), the centre kMaxCentreStep x the window's side.
constexpr float kSlabMargin = 0.05f;
constexpr float kMaxSizeStep = 0.03f;
constexpr float kMaxCentreStep = 0.03f;

// ln step toward `ratio`, `gain` of the way, at most kMaxSizeStep; as a factor.
float sizeStep(float ratio, float gain) {
  if (!(ratio > 0.f)) return 1.f;
  return fmath::fastExp(fmath::clampf(gain * fmath::fastLog(ratio), -kMaxSizeStep, kMaxSizeStep));
}

// Scales D and H, moving the centre along its ray so the front surface stays put (the
// depth correction would otherwise read the move as a velocity).
void rescaleCylinder(Particle& q, float fD, float fH) {
  const float zc = q.p[2] + 0.5f * q.size[0] * (fD - 1.f);
  const float s = zc / q.p[2];
  for (int a = 0; a < 3; ++a) q.p[a] *= s;
  q.size[0] *= fD;
  q.size[1] *= fH;
}

// The silhouette around window b (slab from the surface depth and diameterMm).
bool measureTarget(const Frame& frame, const IntegralChannels& channels, const Box& b,
                   float diameterMm, SilhouetteExtent* e, float* surfaceMm) {
  if (b.empty()) return false;
  // The surface depth as the depth correction reads it (inner 10% of the window).
  const float iw = b.w * 0.1f < 2.f ? 2.f : b.w * 0.1f, ih = b.h * 0.1f < 2.f ? 2.f : b.h * 0.1f;
  const Box inner{b.x + 0.5f * (b.w - iw), b.y + 0.5f * (b.h - ih), iw, ih};
  *surfaceMm = channels.meanDepthMm(clipBox(inner, frame.rgb.width, frame.rgb.height));
  if (!(*surfaceMm > 0.f)) return false;
  const float halfSlabMm = 0.5f * diameterMm + kSlabMargin * *surfaceMm;
  *e = measureSilhouette(frame.depthMm, b, *surfaceMm - halfSlabMm, *surfaceMm + halfSlabMm);
  if (!e->hasWidth) {
    // The run may go on past the window: a target that has grown wider than the window
    // holds (a flat one turning back face-on) would otherwise never be measured again.
    // The width only: the height was measured (or not) in the first window.
    const SilhouetteExtent wide =
        measureSilhouette(frame.depthMm, b, *surfaceMm - halfSlabMm, *surfaceMm + halfSlabMm,
                          kSilhouetteWideGrow, SilhouetteAxes::WidthOnly);
    if (wide.hasWidth) {
      e->hasWidth = true;
      e->widthPx = wide.widthPx;
      e->centreXPx = wide.centreXPx;
    }
  }
  return e->hasWidth || e->hasHeight;
}
}  // namespace

// One axis of the init box against the silhouette's run on it: the ratio side / run and
// the box centre's offset from the run's midpoint (a fraction of the side).
CylinderSizer::Axis CylinderSizer::calibrateAxis(float sidePx, float centrePx, float runPx,
                                                 float runMidPx) {
  Axis a;
  const float ratio = sidePx / runPx;
  if (ratio * kMaxCalibration >= 1.f && ratio <= kMaxCalibration) {
    a.valid = true;
    a.ratio = ratio;
    a.offset = (centrePx - runMidPx) / sidePx;
  }
  return a;
}

void CylinderSizer::calibrate(const Frame& frame, const IntegralChannels& channels, const Box& b,
                              float diameterMm) {
  clear();
  SilhouetteExtent e;
  float surfaceMm = 0.f;
  if (!measureTarget(frame, channels, b, diameterMm, &e, &surfaceMm)) return;
  if (e.hasWidth) _x = calibrateAxis(b.w, b.x + 0.5f * b.w, e.widthPx, e.centreXPx);
  if (e.hasHeight) _y = calibrateAxis(b.h, b.y + 0.5f * b.h, e.heightPx, e.centreYPx);
}

bool CylinderSizer::follow(const Frame& frame, const IntegralChannels& channels,
                           const CameraIntrinsics& k, const Box& b, Particle& est,
                           ParticleFilter& filter) const {
  SilhouetteExtent e;
  float surfaceMm = 0.f;
  if (!measureTarget(frame, channels, b, est.size[0], &e, &surfaceMm)) return false;
  // The measured extent in the init box's terms: the user's box may include parts the
  // measurement misses (a chair's or a person's legs: the middle columns see the floor
  // between them) or background margin; the init frame fixed that ratio and offset.
  float fD = 1.f, fH = 1.f, du = 0.f, dv = 0.f;  // size factors, centre shifts [px]
  const float widthPx = e.widthPx * _x.ratio;
  if (e.hasWidth && _x.valid && widthPx < k.fx) {
    fD = sizeStep(cylinderDiameterMm(widthPx, surfaceMm, k) / est.size[0], _gain);
    const float midPx = e.centreXPx + _x.offset * b.w;
    du = fmath::clampf(_centreGain * (midPx - (b.x + 0.5f * b.w)), -kMaxCentreStep * b.w,
                       kMaxCentreStep * b.w);
  }
  if (e.hasHeight && _y.valid) {
    const float heightMm = cylinderHeightMm(e.heightPx * _y.ratio, surfaceMm, est.size[0] * fD, k);
    fH = sizeStep(heightMm / est.size[1], _gain);
    const float midPx = e.centreYPx + _y.offset * b.h;
    dv = fmath::clampf(_centreGain * (midPx - (b.y + 0.5f * b.h)), -kMaxCentreStep * b.h,
                       kMaxCentreStep * b.h);
  }
  if (fD == 1.f && fH == 1.f && du == 0.f && dv == 0.f) return false;
  // The same change for every particle (its spread stays), velocities untouched: a
  // shift of du px is du z / fx mm at depth z.
  const float xPerZ = du / k.fx, yPerZ = dv / k.fy;
  const int n = filter.size();
  for (int i = -1; i < n; ++i) {
    Particle& q = i < 0 ? est : filter[i];
    rescaleCylinder(q, fD, fH);
    q.p[0] += xPerZ * q.p[2];
    q.p[1] += yPerZ * q.p[2];
  }
  return true;
}

}  // namespace cuetrack
