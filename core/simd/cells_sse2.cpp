// SSE2 cell coder (CellKernels.hpp): 4 windows per instruction, each lane the scalar
// path's IEEE operations (gridEdge, responseAt, angleIndex, magIndexSq).
#include "cuetrack/core/model/CellKernels.hpp"
#if defined(CUETRACK_CELLK_SSE2)
#include <emmintrin.h>

#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack::cellk::sse2 {
namespace {

inline __m128i maxEpi32(__m128i a, __m128i b) {
  const __m128i gt = _mm_cmpgt_epi32(a, b);
  return _mm_or_si128(_mm_and_si128(gt, a), _mm_andnot_si128(gt, b));
}
inline __m128i minEpi32(__m128i a, __m128i b) {
  const __m128i gt = _mm_cmpgt_epi32(a, b);
  return _mm_or_si128(_mm_and_si128(gt, b), _mm_andnot_si128(gt, a));
}
inline __m128i selectEpi32(__m128i mask, __m128i a, __m128i b) {
  return _mm_or_si128(_mm_and_si128(mask, a), _mm_andnot_si128(mask, b));
}
inline __m128 selectPs(__m128 mask, __m128 a, __m128 b) {
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

}  // namespace

int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  if (kind == FeatureKind::Depth) return 0;
  // The feature's cell edges, fractions of the window (Features.hpp: featureEdgeFractions,
  // gridEdge).
  float fx[3], fy[3];
  featureEdgeFractions(f, fx, fy);
  const __m128 kx[3] = {_mm_set1_ps(fx[0]), _mm_set1_ps(fx[1]), _mm_set1_ps(fx[2])};
  const __m128 ky[3] = {_mm_set1_ps(fy[0]), _mm_set1_ps(fy[1]), _mm_set1_ps(fy[2])};
  const __m128 orgX = _mm_set1_ps(static_cast<float>(t.originX));
  const __m128 orgY = _mm_set1_ps(static_cast<float>(t.originY));
  const __m128 half = _mm_set1_ps(4096.5f);
  const __m128i k4096 = _mm_set1_epi32(4096), one = _mm_set1_epi32(1);
  const __m128i zero = _mm_setzero_si128();
  const __m128i width = _mm_set1_epi32(t.width), height = _mm_set1_epi32(t.height);
  const __m128 zeroPs = _mm_setzero_ps();
  const __m128 signMask = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const float minMag = binning(kind).minMag;
  const __m128i magBase = _mm_set1_epi32(static_cast<int>(fmath::floatBits(minMag * minMag) >> 22));
  const __m128i magMax = _mm_set1_epi32(kLutMags - 1);
  const bool gray = kind == FeatureKind::Gray;
  const int stride = t.stride;
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    int idx[4];
    for (int j = 0; j < 4; ++j) idx[j] = order != nullptr ? order[k + j] : k + j;
    static_assert(sizeof(Box) == 4 * sizeof(float), "Box is x, y, w, h");
    __m128 wx = _mm_loadu_ps(&wins[idx[0]].x), wy = _mm_loadu_ps(&wins[idx[1]].x),
           ww = _mm_loadu_ps(&wins[idx[2]].x), wh = _mm_loadu_ps(&wins[idx[3]].x);
    _MM_TRANSPOSE4_PS(wx, wy, ww, wh);
    // gridEdge of each of the feature's edges, clipped to the tables.
    const __m128 ox = _mm_sub_ps(wx, orgX), oy = _mm_sub_ps(wy, orgY);
    const auto roundHalfUp = [&](__m128 v) {  // (int)(v + 4096.5f) - 4096
      return _mm_sub_epi32(_mm_cvttps_epi32(_mm_add_ps(v, half)), k4096);
    };
    __m128i px[3], py[3];
    for (int e = 0; e < 3; ++e) {
      px[e] = minEpi32(maxEpi32(roundHalfUp(_mm_add_ps(ox, _mm_mul_ps(kx[e], ww))), zero), width);
      py[e] = minEpi32(maxEpi32(roundHalfUp(_mm_add_ps(oy, _mm_mul_ps(ky[e], wh))), zero), height);
    }
    // responseAt: every half non-empty.
    const __m128i wl = _mm_sub_epi32(px[1], px[0]), wr = _mm_sub_epi32(px[2], px[1]);
    const __m128i ht = _mm_sub_epi32(py[1], py[0]), hb = _mm_sub_epi32(py[2], py[1]);
    const __m128i ok =
        _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi32(wl, zero), _mm_cmpgt_epi32(wr, zero)),
                      _mm_and_si128(_mm_cmpgt_epi32(ht, zero), _mm_cmpgt_epi32(hb, zero)));
    // Lanes with no rectangle or an invalid window read cell 0 (their cell is kLutCells).
    const __m128i validMask = _mm_cmpgt_epi32(
        _mm_setr_epi32(valid[idx[0]], valid[idx[1]], valid[idx[2]], valid[idx[3]]), zero);
    const __m128i use = _mm_and_si128(ok, validMask);
    // Half sizes (1 on unused lanes: no division by zero). Products < 2^24: the float
    // products are exact, as the scalar path's int ones.
    const __m128 fwl = _mm_cvtepi32_ps(selectEpi32(use, wl, one));
    const __m128 fwr = _mm_cvtepi32_ps(selectEpi32(use, wr, one));
    const __m128 fht = _mm_cvtepi32_ps(selectEpi32(use, ht, one));
    const __m128 fhb = _mm_cvtepi32_ps(selectEpi32(use, hb, one));
    const __m128 fw = _mm_add_ps(fwl, fwr), fh = _mm_add_ps(fht, fhb);
    // Row offsets y * stride (< 2^24: exact in float).
    const __m128 strideF = _mm_set1_ps(static_cast<float>(stride));
    const auto rowOff = [&](__m128i y) {
      return _mm_cvttps_epi32(_mm_mul_ps(_mm_cvtepi32_ps(y), strideF));
    };
    alignas(16) int okv[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(okv), use);
    __m128 gx, gy;
    if (gray) {
      const __m128i rrow[3] = {rowOff(py[0]), rowOff(py[1]), rowOff(py[2])};
      alignas(16) int o[9][4];
      for (int yy = 0; yy < 3; ++yy)
        for (int xx = 0; xx < 3; ++xx)
          _mm_store_si128(reinterpret_cast<__m128i*>(o[yy * 3 + xx]),
                          _mm_and_si128(use, _mm_add_epi32(rrow[yy], px[xx])));
      const uint32_t* g = t.gray;
      __m128i cc[9];
      for (int e = 0; e < 9; ++e)
        cc[e] = _mm_setr_epi32(static_cast<int>(g[o[e][0]]), static_cast<int>(g[o[e][1]]),
                               static_cast<int>(g[o[e][2]]), static_cast<int>(g[o[e][3]]));
      // Quadrant sums (true sums < 2^31: the int32 conversion is the uint32 one).
      const auto quad = [](__m128i p, __m128i q, __m128i r, __m128i u) {
        return _mm_cvtepi32_ps(_mm_add_epi32(_mm_sub_epi32(_mm_sub_epi32(p, q), r), u));
      };
      const __m128 q0 = quad(cc[4], cc[3], cc[1], cc[0]);
      const __m128 q1 = quad(cc[5], cc[4], cc[2], cc[1]);
      const __m128 q2 = quad(cc[7], cc[6], cc[4], cc[3]);
      const __m128 q3 = quad(cc[8], cc[7], cc[5], cc[4]);
      gx = _mm_sub_ps(_mm_div_ps(_mm_add_ps(q1, q3), _mm_mul_ps(fwr, fh)),
                      _mm_div_ps(_mm_add_ps(q0, q2), _mm_mul_ps(fwl, fh)));
      gy = _mm_sub_ps(_mm_div_ps(_mm_add_ps(q2, q3), _mm_mul_ps(fhb, fw)),
                      _mm_div_ps(_mm_add_ps(q0, q1), _mm_mul_ps(fht, fw)));
    } else {
      const __m128 invArea = _mm_div_ps(_mm_set1_ps(1.f), _mm_mul_ps(fw, fh));
      const __m128i r0 = rowOff(py[0]), r1 = rowOff(py[2]);
      alignas(16) int o[4][4];
      _mm_store_si128(reinterpret_cast<__m128i*>(o[0]),
                      _mm_and_si128(use, _mm_add_epi32(r0, px[0])));
      _mm_store_si128(reinterpret_cast<__m128i*>(o[1]),
                      _mm_and_si128(use, _mm_add_epi32(r0, px[2])));
      _mm_store_si128(reinterpret_cast<__m128i*>(o[2]),
                      _mm_and_si128(use, _mm_add_epi32(r1, px[0])));
      _mm_store_si128(reinterpret_cast<__m128i*>(o[3]),
                      _mm_and_si128(use, _mm_add_epi32(r1, px[2])));
      const auto rectOf = [&](const int32_t* tb) {
        __m128i v[4];
        for (int e = 0; e < 4; ++e)
          v[e] = _mm_setr_epi32(tb[o[e][0]], tb[o[e][1]], tb[o[e][2]], tb[o[e][3]]);
        // at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0)
        return _mm_cvtepi32_ps(_mm_add_epi32(_mm_sub_epi32(_mm_sub_epi32(v[3], v[2]), v[1]), v[0]));
      };
      gx = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.5f), rectOf(t.alpha2)), invArea);
      gy = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(0.866025404f), rectOf(t.beta)), invArea);
    }
    // angleIndex
    const __m128 ax = _mm_and_ps(gx, signMask), ay = _mm_and_ps(gy, signMask);
    const __m128 steep = _mm_cmpgt_ps(ay, ax);
    const __m128 mx = selectPs(steep, ay, ax), mn = selectPs(steep, ax, ay);
    const __m128 pos = _mm_cmpgt_ps(mx, zeroPs);
    const __m128i r = _mm_and_si128(
        _mm_castps_si128(pos), _mm_cvttps_epi32(_mm_div_ps(_mm_mul_ps(mn, _mm_set1_ps(64.f)),
                                                           selectPs(pos, mx, _mm_set1_ps(1.f)))));
    alignas(16) int rv[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(rv), r);
    const __m128i s = _mm_setr_epi32(kAngleSectors.sub[rv[0]], kAngleSectors.sub[rv[1]],
                                     kAngleSectors.sub[rv[2]], kAngleSectors.sub[rv[3]]);
    const __m128i iq = selectEpi32(_mm_castps_si128(steep), _mm_sub_epi32(_mm_set1_epi32(7), s), s);
    const __m128i yPos = _mm_castps_si128(_mm_cmpge_ps(gy, zeroPs));
    const __m128i xPos = _mm_castps_si128(_mm_cmpge_ps(gx, zeroPs));
    const __m128i xNeg = _mm_castps_si128(_mm_cmplt_ps(gx, zeroPs));
    const __m128i upper = selectEpi32(xPos, iq, _mm_sub_epi32(_mm_set1_epi32(15), iq));
    const __m128i lower = selectEpi32(xNeg, _mm_add_epi32(_mm_set1_epi32(16), iq),
                                      _mm_sub_epi32(_mm_set1_epi32(31), iq));
    const __m128i angle = selectEpi32(yPos, upper, lower);
    // magIndexSq
    const __m128 mag2 = _mm_add_ps(_mm_mul_ps(gx, gx), _mm_mul_ps(gy, gy));
    __m128i mi = _mm_sub_epi32(_mm_srli_epi32(_mm_castps_si128(mag2), 22), magBase);
    mi = minEpi32(maxEpi32(mi, zero), magMax);
    const __m128i cell = _mm_add_epi32(_mm_mullo_epi16(angle, _mm_set1_epi32(kLutMags)), mi);
    alignas(16) int cv[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(cv), cell);
    for (int j = 0; j < 4; ++j) cells[idx[j]] = static_cast<uint16_t>(okv[j] ? cv[j] : kLutCells);
  }
  return k;
}

}  // namespace cuetrack::cellk::sse2
#endif
