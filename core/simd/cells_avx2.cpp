// AVX2 cell coder (CellKernels.hpp): the SSE2 coder's lanes, 8 windows at a time, with
// the table reads as gathers. Each lane is the scalar path's IEEE operations
// (gridEdge, responseAt, angleIndex, magIndexSq). Only this file is built with
// -mavx2; the dispatcher calls it after a CPUID check. The last n % 8 windows go to SSE2.
#include "cuetrack/core/model/CellKernels.hpp"
#if defined(CUETRACK_CELLK_AVX2)
#include <immintrin.h>

#include "cuetrack/core/model/WeakClassifier.hpp"

namespace cuetrack::cellk::avx2 {

namespace {

// kAngleSectors widened to int32 for the gather.
struct Sectors32 {
  int32_t sub[65];
  constexpr Sectors32() : sub() {
    for (int i = 0; i <= 64; ++i) sub[i] = kAngleSectors.sub[i];
  }
};
constexpr Sectors32 kSectors32{};

inline __m256i select(__m256i mask, __m256i a, __m256i b) {
  return _mm256_blendv_epi8(b, a, mask);
}
inline __m256 select(__m256 mask, __m256 a, __m256 b) {
  return _mm256_blendv_ps(b, a, mask);
}
inline __m256i gather(const void* table, __m256i offsets) {
  return _mm256_i32gather_epi32(static_cast<const int*>(table), offsets, 4);
}

}  // namespace

int codeFrame(FeatureKind kind, const Feature& f, const FrameTables& t, const Box* wins,
              const uint8_t* valid, int n, uint16_t* cells, const uint16_t* order) {
  if (kind == FeatureKind::Depth) return 0;
  // The feature's cell edges, fractions of the window (Features.hpp: featureEdgeFractions,
  // gridEdge).
  float fx[3], fy[3];
  featureEdgeFractions(f, fx, fy);
  const __m256 kx[3] = {_mm256_set1_ps(fx[0]), _mm256_set1_ps(fx[1]), _mm256_set1_ps(fx[2])};
  const __m256 ky[3] = {_mm256_set1_ps(fy[0]), _mm256_set1_ps(fy[1]), _mm256_set1_ps(fy[2])};
  const __m256 orgX = _mm256_set1_ps(static_cast<float>(t.originX));
  const __m256 orgY = _mm256_set1_ps(static_cast<float>(t.originY));
  const __m256 half = _mm256_set1_ps(4096.5f);
  const __m256i k4096 = _mm256_set1_epi32(4096), one = _mm256_set1_epi32(1);
  const __m256i zero = _mm256_setzero_si256();
  const __m256i width = _mm256_set1_epi32(t.width), height = _mm256_set1_epi32(t.height);
  const __m256 zeroPs = _mm256_setzero_ps(), onePs = _mm256_set1_ps(1.f);
  const __m256 signMask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
  const float minMag = binning(kind).minMag;
  const __m256i magBase =
      _mm256_set1_epi32(static_cast<int>(fmath::floatBits(minMag * minMag) >> 22));
  const __m256i magMax = _mm256_set1_epi32(kLutMags - 1);
  const __m256 strideF = _mm256_set1_ps(static_cast<float>(t.stride));
  const bool gray = kind == FeatureKind::Gray;
  const auto rowOff = [&](__m256i y) {  // y * stride < 2^24: exact in float
    return _mm256_cvttps_epi32(_mm256_mul_ps(_mm256_cvtepi32_ps(y), strideF));
  };
  const auto roundHalfUp = [&](__m256 v) {  // (int)(v + 4096.5f) - 4096
    return _mm256_sub_epi32(_mm256_cvttps_epi32(_mm256_add_ps(v, half)), k4096);
  };
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    int idx[8];
    for (int j = 0; j < 8; ++j) idx[j] = order != nullptr ? order[k + j] : k + j;
    static_assert(sizeof(Box) == 4 * sizeof(float), "Box is x, y, w, h");
    // Windows j and j + 4 share a row; transpose each 128-bit half to x, y, w, h.
    __m256 b[4];
    for (int j = 0; j < 4; ++j)
      b[j] = _mm256_set_m128(_mm_loadu_ps(&wins[idx[j + 4]].x), _mm_loadu_ps(&wins[idx[j]].x));
    const __m256 t0 = _mm256_unpacklo_ps(b[0], b[1]), t1 = _mm256_unpacklo_ps(b[2], b[3]);
    const __m256 t2 = _mm256_unpackhi_ps(b[0], b[1]), t3 = _mm256_unpackhi_ps(b[2], b[3]);
    const __m256 wx = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 wy = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 ww = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 wh = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(3, 2, 3, 2));
    // gridEdge of each of the feature's edges, clipped to the tables.
    const __m256 ox = _mm256_sub_ps(wx, orgX), oy = _mm256_sub_ps(wy, orgY);
    __m256i px[3], py[3];
    for (int e = 0; e < 3; ++e) {
      px[e] = _mm256_min_epi32(
          _mm256_max_epi32(roundHalfUp(_mm256_add_ps(ox, _mm256_mul_ps(kx[e], ww))), zero), width);
      py[e] = _mm256_min_epi32(
          _mm256_max_epi32(roundHalfUp(_mm256_add_ps(oy, _mm256_mul_ps(ky[e], wh))), zero), height);
    }
    // responseAt: every half non-empty.
    const __m256i wl = _mm256_sub_epi32(px[1], px[0]), wr = _mm256_sub_epi32(px[2], px[1]);
    const __m256i ht = _mm256_sub_epi32(py[1], py[0]), hb = _mm256_sub_epi32(py[2], py[1]);
    const __m256i ok = _mm256_and_si256(
        _mm256_and_si256(_mm256_cmpgt_epi32(wl, zero), _mm256_cmpgt_epi32(wr, zero)),
        _mm256_and_si256(_mm256_cmpgt_epi32(ht, zero), _mm256_cmpgt_epi32(hb, zero)));
    // Lanes with no rectangle or an invalid window read cell 0 (their cell is kLutCells).
    const __m256i validMask = _mm256_cmpgt_epi32(
        _mm256_setr_epi32(valid[idx[0]], valid[idx[1]], valid[idx[2]], valid[idx[3]], valid[idx[4]],
                          valid[idx[5]], valid[idx[6]], valid[idx[7]]),
        zero);
    const __m256i use = _mm256_and_si256(ok, validMask);
    // Half sizes (1 on unused lanes: no division by zero). Products < 2^24: the float
    // products are exact, as the scalar path's int ones.
    const __m256 fwl = _mm256_cvtepi32_ps(select(use, wl, one));
    const __m256 fwr = _mm256_cvtepi32_ps(select(use, wr, one));
    const __m256 fht = _mm256_cvtepi32_ps(select(use, ht, one));
    const __m256 fhb = _mm256_cvtepi32_ps(select(use, hb, one));
    const __m256 fw = _mm256_add_ps(fwl, fwr), fh = _mm256_add_ps(fht, fhb);
    __m256 gx, gy;
    if (gray) {
      const __m256i rrow[3] = {rowOff(py[0]), rowOff(py[1]), rowOff(py[2])};
      __m256i cc[9];
      for (int yy = 0; yy < 3; ++yy)
        for (int xx = 0; xx < 3; ++xx)
          cc[yy * 3 + xx] =
              gather(t.gray, _mm256_and_si256(use, _mm256_add_epi32(rrow[yy], px[xx])));
      // Quadrant sums (true sums < 2^31: the int32 conversion is the uint32 one).
      const auto quad = [](__m256i p, __m256i q, __m256i r, __m256i u) {
        return _mm256_cvtepi32_ps(_mm256_add_epi32(_mm256_sub_epi32(_mm256_sub_epi32(p, q), r), u));
      };
      const __m256 q0 = quad(cc[4], cc[3], cc[1], cc[0]);
      const __m256 q1 = quad(cc[5], cc[4], cc[2], cc[1]);
      const __m256 q2 = quad(cc[7], cc[6], cc[4], cc[3]);
      const __m256 q3 = quad(cc[8], cc[7], cc[5], cc[4]);
      gx = _mm256_sub_ps(_mm256_div_ps(_mm256_add_ps(q1, q3), _mm256_mul_ps(fwr, fh)),
                         _mm256_div_ps(_mm256_add_ps(q0, q2), _mm256_mul_ps(fwl, fh)));
      gy = _mm256_sub_ps(_mm256_div_ps(_mm256_add_ps(q2, q3), _mm256_mul_ps(fhb, fw)),
                         _mm256_div_ps(_mm256_add_ps(q0, q1), _mm256_mul_ps(fht, fw)));
    } else {
      const __m256 invArea = _mm256_div_ps(onePs, _mm256_mul_ps(fw, fh));
      const __m256i r0 = rowOff(py[0]), r1 = rowOff(py[2]);
      const __m256i o[4] = {_mm256_and_si256(use, _mm256_add_epi32(r0, px[0])),
                            _mm256_and_si256(use, _mm256_add_epi32(r0, px[2])),
                            _mm256_and_si256(use, _mm256_add_epi32(r1, px[0])),
                            _mm256_and_si256(use, _mm256_add_epi32(r1, px[2]))};
      const auto rectOf = [&](const int32_t* tb) {
        // at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0)
        return _mm256_cvtepi32_ps(
            _mm256_add_epi32(_mm256_sub_epi32(_mm256_sub_epi32(gather(tb, o[3]), gather(tb, o[2])),
                                              gather(tb, o[1])),
                             gather(tb, o[0])));
      };
      gx = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), rectOf(t.alpha2)), invArea);
      gy = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.866025404f), rectOf(t.beta)), invArea);
    }
    // angleIndex
    const __m256 ax = _mm256_and_ps(gx, signMask), ay = _mm256_and_ps(gy, signMask);
    const __m256 steep = _mm256_cmp_ps(ay, ax, _CMP_GT_OQ);
    const __m256 mx = select(steep, ay, ax), mn = select(steep, ax, ay);
    const __m256 pos = _mm256_cmp_ps(mx, zeroPs, _CMP_GT_OQ);
    const __m256i r =
        _mm256_and_si256(_mm256_castps_si256(pos),
                         _mm256_cvttps_epi32(_mm256_div_ps(_mm256_mul_ps(mn, _mm256_set1_ps(64.f)),
                                                           select(pos, mx, onePs))));
    // r is in [0, 64] on every lane that reads it; clamped so no lane can read outside.
    const __m256i s =
        gather(kSectors32.sub, _mm256_min_epi32(_mm256_max_epi32(r, zero), _mm256_set1_epi32(64)));
    const __m256i steepI = _mm256_castps_si256(steep);
    const __m256i iq = select(steepI, _mm256_sub_epi32(_mm256_set1_epi32(7), s), s);
    const __m256i yPos = _mm256_castps_si256(_mm256_cmp_ps(gy, zeroPs, _CMP_GE_OQ));
    const __m256i xPos = _mm256_castps_si256(_mm256_cmp_ps(gx, zeroPs, _CMP_GE_OQ));
    const __m256i xNeg = _mm256_castps_si256(_mm256_cmp_ps(gx, zeroPs, _CMP_LT_OQ));
    const __m256i upper = select(xPos, iq, _mm256_sub_epi32(_mm256_set1_epi32(15), iq));
    const __m256i lower = select(xNeg, _mm256_add_epi32(_mm256_set1_epi32(16), iq),
                                 _mm256_sub_epi32(_mm256_set1_epi32(31), iq));
    const __m256i angle = select(yPos, upper, lower);
    // magIndexSq
    const __m256 mag2 = _mm256_add_ps(_mm256_mul_ps(gx, gx), _mm256_mul_ps(gy, gy));
    __m256i mi = _mm256_sub_epi32(_mm256_srli_epi32(_mm256_castps_si256(mag2), 22), magBase);
    mi = _mm256_min_epi32(_mm256_max_epi32(mi, zero), magMax);
    const __m256i cell =
        select(use, _mm256_add_epi32(_mm256_mullo_epi32(angle, _mm256_set1_epi32(kLutMags)), mi),
               _mm256_set1_epi32(kLutCells));
    alignas(32) int cv[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(cv), cell);
    for (int j = 0; j < 8; ++j) cells[idx[j]] = static_cast<uint16_t>(cv[j]);
  }
  if (order != nullptr)
    return k + sse2::codeFrame(kind, f, t, wins, valid, n - k, cells, order + k);
  return k + sse2::codeFrame(kind, f, t, wins + k, valid + k, n - k, cells + k, nullptr);
}

}  // namespace cuetrack::cellk::avx2
#endif
