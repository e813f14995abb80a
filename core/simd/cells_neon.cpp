// aarch64 NEON cell coder (CellKernels.hpp): the SSE2 coder's lanes, each the scalar
// path's IEEE operations (gridEdge, responseAt, angleIndex, magIndexSq). aarch64
// NEON arithmetic and division are IEEE, so it is bit-exact; armhf uses the scalar coder.
#include "cuetrack/core/model/CellKernels.hpp"
#if defined(CUETRACK_CELLK_NEON)
#include <arm_neon.h>

#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack::cellk::neon {

namespace {

inline int32x4_t load4(int32_t a, int32_t b, int32_t c, int32_t d) {
  const int32_t v[4] = {a, b, c, d};
  return vld1q_s32(v);
}

}  // namespace

int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  if (kind == FeatureKind::Depth) return 0;
  // The feature's cell edges, fractions of the window (Features.hpp: featureEdgeFractions,
  // gridEdge).
  float fx[3], fy[3];
  featureEdgeFractions(f, fx, fy);
  const float32x4_t kx[3] = {vdupq_n_f32(fx[0]), vdupq_n_f32(fx[1]), vdupq_n_f32(fx[2])};
  const float32x4_t ky[3] = {vdupq_n_f32(fy[0]), vdupq_n_f32(fy[1]), vdupq_n_f32(fy[2])};
  const float32x4_t orgX = vdupq_n_f32(static_cast<float>(t.originX));
  const float32x4_t orgY = vdupq_n_f32(static_cast<float>(t.originY));
  const float32x4_t half = vdupq_n_f32(4096.5f);
  const int32x4_t k4096 = vdupq_n_s32(4096), one = vdupq_n_s32(1);
  const int32x4_t zero = vdupq_n_s32(0);
  const int32x4_t width = vdupq_n_s32(t.width), height = vdupq_n_s32(t.height);
  const float32x4_t zeroPs = vdupq_n_f32(0.f), onePs = vdupq_n_f32(1.f);
  const float minMag = binning(kind).minMag;
  const int32x4_t magBase = vdupq_n_s32(static_cast<int>(fmath::floatBits(minMag * minMag) >> 22));
  const int32x4_t magMax = vdupq_n_s32(kLutMags - 1);
  const float32x4_t strideF = vdupq_n_f32(static_cast<float>(t.stride));
  const bool gray = kind == FeatureKind::Gray;
  const auto rowOff = [&](int32x4_t y) {
    return vcvtq_s32_f32(vmulq_f32(vcvtq_f32_s32(y), strideF));
  };
  const auto roundHalfUp = [&](float32x4_t v) {  // (int)(v + 4096.5f) - 4096
    return vsubq_s32(vcvtq_s32_f32(vaddq_f32(v, half)), k4096);
  };
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    int idx[4];
    for (int j = 0; j < 4; ++j) idx[j] = order != nullptr ? order[k + j] : k + j;
    static_assert(sizeof(Box) == 4 * sizeof(float), "Box is x, y, w, h");
    // Transpose the four windows to x, y, w, h vectors.
    float32x4x4_t b4;
    b4.val[0] = vld1q_f32(&wins[idx[0]].x);
    b4.val[1] = vld1q_f32(&wins[idx[1]].x);
    b4.val[2] = vld1q_f32(&wins[idx[2]].x);
    b4.val[3] = vld1q_f32(&wins[idx[3]].x);
    const float32x4_t t01l = vtrn1q_f32(b4.val[0], b4.val[1]),
                      t01h = vtrn2q_f32(b4.val[0], b4.val[1]);
    const float32x4_t t23l = vtrn1q_f32(b4.val[2], b4.val[3]),
                      t23h = vtrn2q_f32(b4.val[2], b4.val[3]);
    const float32x4_t wx =
        vreinterpretq_f32_f64(vtrn1q_f64(vreinterpretq_f64_f32(t01l), vreinterpretq_f64_f32(t23l)));
    const float32x4_t wy =
        vreinterpretq_f32_f64(vtrn1q_f64(vreinterpretq_f64_f32(t01h), vreinterpretq_f64_f32(t23h)));
    const float32x4_t ww =
        vreinterpretq_f32_f64(vtrn2q_f64(vreinterpretq_f64_f32(t01l), vreinterpretq_f64_f32(t23l)));
    const float32x4_t wh =
        vreinterpretq_f32_f64(vtrn2q_f64(vreinterpretq_f64_f32(t01h), vreinterpretq_f64_f32(t23h)));
    // gridEdge of each of the feature's edges, clipped to the tables.
    const float32x4_t ox = vsubq_f32(wx, orgX), oy = vsubq_f32(wy, orgY);
    int32x4_t px[3], py[3];
    for (int e = 0; e < 3; ++e) {
      px[e] = vminq_s32(vmaxq_s32(roundHalfUp(vaddq_f32(ox, vmulq_f32(kx[e], ww))), zero), width);
      py[e] = vminq_s32(vmaxq_s32(roundHalfUp(vaddq_f32(oy, vmulq_f32(ky[e], wh))), zero), height);
    }
    // responseAt: every half non-empty.
    const int32x4_t wl = vsubq_s32(px[1], px[0]), wr = vsubq_s32(px[2], px[1]);
    const int32x4_t ht = vsubq_s32(py[1], py[0]), hb = vsubq_s32(py[2], py[1]);
    const uint32x4_t ok = vandq_u32(vandq_u32(vcgtq_s32(wl, zero), vcgtq_s32(wr, zero)),
                                    vandq_u32(vcgtq_s32(ht, zero), vcgtq_s32(hb, zero)));
    // Lanes with no rectangle or an invalid window read cell 0 (their cell is kLutCells).
    const uint32x4_t validMask =
        vcgtq_s32(load4(valid[idx[0]], valid[idx[1]], valid[idx[2]], valid[idx[3]]), zero);
    const uint32x4_t use = vandq_u32(ok, validMask);
    const int32x4_t useS = vreinterpretq_s32_u32(use);
    // Half sizes (1 on unused lanes: no division by zero). Products < 2^24: the float
    // products are exact, as the scalar path's int ones.
    const float32x4_t fwl = vcvtq_f32_s32(vbslq_s32(use, wl, one));
    const float32x4_t fwr = vcvtq_f32_s32(vbslq_s32(use, wr, one));
    const float32x4_t fht = vcvtq_f32_s32(vbslq_s32(use, ht, one));
    const float32x4_t fhb = vcvtq_f32_s32(vbslq_s32(use, hb, one));
    const float32x4_t fw = vaddq_f32(fwl, fwr), fh = vaddq_f32(fht, fhb);
    float32x4_t gx, gy;
    if (gray) {
      const int32x4_t rrow[3] = {rowOff(py[0]), rowOff(py[1]), rowOff(py[2])};
      int32_t o[9][4];
      for (int yy = 0; yy < 3; ++yy)
        for (int xx = 0; xx < 3; ++xx)
          vst1q_s32(o[yy * 3 + xx], vandq_s32(useS, vaddq_s32(rrow[yy], px[xx])));
      const uint32_t* g = t.gray;
      uint32x4_t cc[9];
      for (int e = 0; e < 9; ++e) {
        const uint32_t v[4] = {g[o[e][0]], g[o[e][1]], g[o[e][2]], g[o[e][3]]};
        cc[e] = vld1q_u32(v);
      }
      // Quadrant sums (true sums < 2^31: the int32 conversion is the uint32 one).
      const auto quad = [](uint32x4_t p, uint32x4_t q, uint32x4_t r, uint32x4_t u) {
        return vcvtq_f32_s32(vreinterpretq_s32_u32(vaddq_u32(vsubq_u32(vsubq_u32(p, q), r), u)));
      };
      const float32x4_t q0 = quad(cc[4], cc[3], cc[1], cc[0]);
      const float32x4_t q1 = quad(cc[5], cc[4], cc[2], cc[1]);
      const float32x4_t q2 = quad(cc[7], cc[6], cc[4], cc[3]);
      const float32x4_t q3 = quad(cc[8], cc[7], cc[5], cc[4]);
      gx = vsubq_f32(vdivq_f32(vaddq_f32(q1, q3), vmulq_f32(fwr, fh)),
                     vdivq_f32(vaddq_f32(q0, q2), vmulq_f32(fwl, fh)));
      gy = vsubq_f32(vdivq_f32(vaddq_f32(q2, q3), vmulq_f32(fhb, fw)),
                     vdivq_f32(vaddq_f32(q0, q1), vmulq_f32(fht, fw)));
    } else {
      const float32x4_t invArea = vdivq_f32(onePs, vmulq_f32(fw, fh));
      const int32x4_t r0 = rowOff(py[0]), r1 = rowOff(py[2]);
      int32_t o[4][4];
      vst1q_s32(o[0], vandq_s32(useS, vaddq_s32(r0, px[0])));
      vst1q_s32(o[1], vandq_s32(useS, vaddq_s32(r0, px[2])));
      vst1q_s32(o[2], vandq_s32(useS, vaddq_s32(r1, px[0])));
      vst1q_s32(o[3], vandq_s32(useS, vaddq_s32(r1, px[2])));
      const auto rectOf = [&](const int32_t* tb) {
        int32x4_t v[4];
        for (int e = 0; e < 4; ++e)
          v[e] = load4(tb[o[e][0]], tb[o[e][1]], tb[o[e][2]], tb[o[e][3]]);
        // at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0)
        return vcvtq_f32_s32(vaddq_s32(vsubq_s32(vsubq_s32(v[3], v[2]), v[1]), v[0]));
      };
      gx = vmulq_f32(vmulq_f32(vdupq_n_f32(0.5f), rectOf(t.alpha2)), invArea);
      gy = vmulq_f32(vmulq_f32(vdupq_n_f32(0.866025404f), rectOf(t.beta)), invArea);
    }
    // angleIndex
    const float32x4_t ax = vabsq_f32(gx), ay = vabsq_f32(gy);
    const uint32x4_t steep = vcgtq_f32(ay, ax);
    const float32x4_t mx = vbslq_f32(steep, ay, ax), mn = vbslq_f32(steep, ax, ay);
    const uint32x4_t pos = vcgtq_f32(mx, zeroPs);
    const int32x4_t r = vandq_s32(
        vreinterpretq_s32_u32(pos),
        vcvtq_s32_f32(vdivq_f32(vmulq_f32(mn, vdupq_n_f32(64.f)), vbslq_f32(pos, mx, onePs))));
    int32_t rv[4];
    vst1q_s32(rv, r);
    const int32x4_t s = load4(kAngleSectors.sub[rv[0]], kAngleSectors.sub[rv[1]],
                              kAngleSectors.sub[rv[2]], kAngleSectors.sub[rv[3]]);
    const int32x4_t iq = vbslq_s32(steep, vsubq_s32(vdupq_n_s32(7), s), s);
    const uint32x4_t yPos = vcgeq_f32(gy, zeroPs);
    const uint32x4_t xPos = vcgeq_f32(gx, zeroPs);
    const uint32x4_t xNeg = vcltq_f32(gx, zeroPs);
    const int32x4_t upper = vbslq_s32(xPos, iq, vsubq_s32(vdupq_n_s32(15), iq));
    const int32x4_t lower =
        vbslq_s32(xNeg, vaddq_s32(vdupq_n_s32(16), iq), vsubq_s32(vdupq_n_s32(31), iq));
    const int32x4_t angle = vbslq_s32(yPos, upper, lower);
    // magIndexSq
    const float32x4_t mag2 = vaddq_f32(vmulq_f32(gx, gx), vmulq_f32(gy, gy));
    int32x4_t mi =
        vsubq_s32(vreinterpretq_s32_u32(vshrq_n_u32(vreinterpretq_u32_f32(mag2), 22)), magBase);
    mi = vminq_s32(vmaxq_s32(mi, zero), magMax);
    // Invalid lanes get kLutCells.
    const int32x4_t cell =
        vbslq_s32(use, vmlaq_s32(mi, angle, vdupq_n_s32(kLutMags)), vdupq_n_s32(kLutCells));
    int32_t cv[4];
    vst1q_s32(cv, cell);
    for (int j = 0; j < 4; ++j) cells[idx[j]] = static_cast<uint16_t>(cv[j]);
  }
  return k;
}

}  // namespace cuetrack::cellk::neon
#endif
