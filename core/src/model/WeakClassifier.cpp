#include "cuetrack/core/model/WeakClassifier.hpp"

#include "cuetrack/core/kernels/FitKernels.hpp"

namespace cuetrack {

namespace {

// Exponent + top mantissa bit of m^2: 4 steps per octave of m.
int rawMagCode(float mag) {
  const float m2 = mag * mag;
  return static_cast<int>(fmath::floatBits(m2) >> 22);
}

void shares(float angle, float mag, FeatureKind kind, uint8_t* a, float* wc, float* wa, float* wb) {
  const KindBinning& k = binning(kind);
  const float t = fmath::clampf((mag - k.innerMag) / (k.outerMag - k.innerMag), 0.f, 1.f);
  const float pos = angle * (static_cast<float>(kOrientBins) / fmath::kTwoPi) - 0.5f;
  int i = fmath::floorToInt(pos);
  const float frac = pos - static_cast<float>(i);
  if (i < 0) i += kOrientBins;
  if (i >= kOrientBins) i -= kOrientBins;
  *a = static_cast<uint8_t>(i);
  *wc = 1.f - t;
  *wa = t * (1.f - frac);
  *wb = t * frac;
}

constexpr float kVarPrior = 0.05f;  // ln-units^2 added to every fitted variance
// Each class's density in a bin is its lognormal plus this x the bin's mass, per ln-unit (a
// uniform outlier part). Without it the negatives' lognormal underflows beside the
// positives' mode and f is exactly +1 over a wide band of magnitudes there, so every weak
// classifier saturates, windows near the target and on part of it all score c = 1, and the
// particles' weights cannot tell them apart (docs/algorithm.md).
constexpr float kDensityFloor = 0.02f;
constexpr float kEps = 1e-7f;

}  // namespace

float magOfIndex(int idx, FeatureKind kind) {
  const int base = rawMagCode(binning(kind).minMag);
  const uint32_t bits = (static_cast<uint32_t>(base + idx) << 22) | (1u << 21);
  return fmath::sqrtf(fmath::bitsFloat(bits));
}

namespace {
float lnMagOfIndex(int q, FeatureKind kind) {
  const float m = magOfIndex(q, kind);
  const float minMag = binning(kind).minMag;
  return fmath::fastLog(m > minMag ? m : minMag);
}
}  // namespace

void ShareTable::build() {
  for (int k = 0; k < kNumFeatureKinds; ++k)
    for (int q = 0; q < kLutMags; ++q) lnMag[k][q] = lnMagOfIndex(q, static_cast<FeatureKind>(k));
  for (int k = 0; k < kNumFeatureKinds; ++k)
    for (int o = 0; o < kLutAngles; ++o) {
      const float angle = (static_cast<float>(o) + 0.5f) * (fmath::kTwoPi / kLutAngles);
      for (int q = 0; q < kLutMags; ++q) {
        const int c = o * kLutMags + q;
        const FeatureKind kind = static_cast<FeatureKind>(k);
        shares(angle, magOfIndex(q, kind), kind, &a[k][c], &wCentre[k][c], &wA[k][c], &wB[k][c]);
      }
    }
}

Code encode(const Response& r, FeatureKind kind) {
  Code c;
  if (!r.valid) {
    c.wA = 1.f;  // all into kInvalidBin (binA == binB == kInvalidBin)
    return c;
  }
  const float minMag = binning(kind).minMag;
  const float mag = r.mag();
  c.lnMag = fmath::fastLog(mag > minMag ? mag : minMag);
  uint8_t a;
  shares(r.angle(), mag, kind, &a, &c.wCentre, &c.wA, &c.wB);
  c.binA = static_cast<uint8_t>(1 + a);
  c.binB = static_cast<uint8_t>(1 + (a + 1 == kOrientBins ? 0 : a + 1));
  c.angleIdx = static_cast<uint8_t>(angleIndex(r.x, r.y));
  c.magIdx = static_cast<uint8_t>(magIndexSq(r.magSquared(), kind));
  return c;
}

float WeakClassifier::binnedError(const Code* codes, const float* w, const int8_t* y, int n) {
  float acc[2][kNumBins] = {};
  for (int i = 0; i < n; ++i) {
    const Code& c = codes[i];
    float* h = acc[y[i] > 0 ? 0 : 1];
    const float wi = w[i];
    h[0] += wi * c.wCentre;
    h[c.binA] += wi * c.wA;
    h[c.binB] += wi * c.wB;
  }
  float err = 0.f;
  for (int b = 0; b < kNumBins; ++b) {
    const float s = acc[0][b] + acc[1][b];
    if (s > kEps) err += 4.f * acc[0][b] * acc[1][b] / s;
  }
  return err;
}

float WeakClassifier::binnedErrorSplit(const Code* codes, const float* w, int split, int n) {
  float p[kNumBins] = {}, q[kNumBins] = {};
  for (int i = 0; i < split; ++i) {
    const Code& c = codes[i];
    const float wi = w[i];
    p[0] += wi * c.wCentre;
    p[c.binA] += wi * c.wA;
    p[c.binB] += wi * c.wB;
  }
  for (int i = split; i < n; ++i) {
    const Code& c = codes[i];
    const float wi = w[i];
    q[0] += wi * c.wCentre;
    q[c.binA] += wi * c.wA;
    q[c.binB] += wi * c.wB;
  }
  float err = 0.f;
  for (int b = 0; b < kNumBins; ++b) {
    const float s = p[b] + q[b];
    if (s > kEps) err += 4.f * p[b] * q[b] / s;
  }
  return err;
}

namespace {

// One feature's histogram for binnedErrorSplit4. The centre bin (0) sits in its own
// variable: binA and binB are never 0, so every example's centre share forms a chain of
// register additions instead of a chain through memory.
struct SplitHist {
  float centre = 0.f;
  float bin[kNumBins] = {};  // bin[0] unused
};

inline void addCode(SplitHist& h, const Code& c, float wi) {
  h.centre += wi * c.wCentre;
  h.bin[c.binA] += wi * c.wA;
  h.bin[c.binB] += wi * c.wB;
}

inline float splitError(const SplitHist& p, const SplitHist& q) {
  float err = 0.f;
  for (int b = 0; b < kNumBins; ++b) {
    const float pb = b == 0 ? p.centre : p.bin[b], qb = b == 0 ? q.centre : q.bin[b];
    const float s = pb + qb;
    if (s > kEps) err += 4.f * pb * qb / s;
  }
  return err;
}

}  // namespace

void WeakClassifier::binnedErrorSplit4(const Code* const codes[4], const float* w, int split, int n,
                                       float err[4]) {
  SplitHist p0, p1, p2, p3, q0, q1, q2, q3;
  const Code *c0 = codes[0], *c1 = codes[1], *c2 = codes[2], *c3 = codes[3];
  for (int i = 0; i < split; ++i) {
    const float wi = w[i];
    addCode(p0, c0[i], wi);
    addCode(p1, c1[i], wi);
    addCode(p2, c2[i], wi);
    addCode(p3, c3[i], wi);
  }
  for (int i = split; i < n; ++i) {
    const float wi = w[i];
    addCode(q0, c0[i], wi);
    addCode(q1, c1[i], wi);
    addCode(q2, c2[i], wi);
    addCode(q3, c3[i], wi);
  }
  err[0] = splitError(p0, q0);
  err[1] = splitError(p1, q1);
  err[2] = splitError(p2, q2);
  err[3] = splitError(p3, q3);
}

void WeakClassifier::fit(const Code* codes, const float* w, const int8_t* y, int n,
                         FeatureKind kind, const ShareTable* table) {
  _kind = kind;
  // s[class][bin][0..2]: sum w*share, sum w*share*ln m, sum w*share*(ln m)^2
  float s[2][kNumBins][3] = {};
  for (int i = 0; i < n; ++i) {
    const Code& c = codes[i];
    const int cls = y[i] > 0 ? 0 : 1;
    const float wi = w[i];
    if (!c.valid()) {
      s[cls][kInvalidBin][0] += wi;
      continue;
    }
    const float l = c.lnMag, l2 = c.lnMag * c.lnMag;
    const int bins[3] = {0, c.binA, c.binB};
    const float sh[3] = {c.wCentre, c.wA, c.wB};
    for (int k = 0; k < 3; ++k) {
      const float ws = wi * sh[k];
      s[cls][bins[k]][0] += ws;
      s[cls][bins[k]][1] += ws * l;
      s[cls][bins[k]][2] += ws * l2;
    }
  }
  {
    const float p = s[0][kInvalidBin][0], q = s[1][kInvalidBin][0];
    _invalid = (p - q) / (p + q + kEps);
    _lut[kLutCells] = _invalid;
  }
  // Weighted likelihood of each magnitude step per bin and class:
  // mass / sigma * exp(-(ln m - mu)^2 / (2 sigma^2)) (the 1/(m sqrt(2 pi)) cancels in the ratio).
  float dens[2][kOrientBins + 1][kLutMags];
  float lnmLocal[kLutMags];
  const int k = static_cast<int>(kind);
  const float* lnm = lnmLocal;
  if (table != nullptr) {
    lnm = table->lnMag[k];
  } else {
    for (int q = 0; q < kLutMags; ++q) lnmLocal[q] = lnMagOfIndex(q, kind);
  }
  for (int cls = 0; cls < 2; ++cls) {
    for (int b = 0; b <= kOrientBins; ++b) {
      const float mass = s[cls][b][0];
      if (mass <= kEps) {
        for (int q = 0; q < kLutMags; ++q) dens[cls][b][q] = 0.f;
        continue;
      }
      const float mu = s[cls][b][1] / mass;
      float var = s[cls][b][2] / mass - mu * mu;
      if (var < 0.f) var = 0.f;
      var += kVarPrior;
      const float norm = mass / fmath::sqrtf(var);
      fitk::densRow(lnm, mu, -0.5f / var, norm, dens[cls][b], kLutMags);
      const float floorDens = kDensityFloor * mass;
      for (int q = 0; q < kLutMags; ++q) dens[cls][b][q] += floorDens;
    }
  }
  static_assert(kLutMags % 4 == 0, "the fit kernels take 4 steps at a time");
  if (table != nullptr) {
    // Shares from the table; a (so the two outer bins) is constant along a row.
    for (int o = 0; o < kLutAngles; ++o) {
      const int c = o * kLutMags;
      const int a = table->a[k][c];
      const int b1 = 1 + a, b2 = 1 + (a + 1 == kOrientBins ? 0 : a + 1);
      fitk::bakeRow(table->wCentre[k] + c, table->wA[k] + c, table->wB[k] + c, dens[0][0],
                    dens[0][b1], dens[0][b2], dens[1][0], dens[1][b1], dens[1][b2], kEps, _lut + c,
                    kLutMags);
    }
    return;
  }
  for (int o = 0; o < kLutAngles; ++o) {
    const float angle = (static_cast<float>(o) + 0.5f) * (fmath::kTwoPi / kLutAngles);
    for (int q = 0; q < kLutMags; ++q) {
      uint8_t a;
      float wc, wa, wb;
      shares(angle, magOfIndex(q, kind), kind, &a, &wc, &wa, &wb);
      const int b1 = 1 + a, b2 = 1 + (a + 1 == kOrientBins ? 0 : a + 1);
      const float p = wc * dens[0][0][q] + wa * dens[0][b1][q] + wb * dens[0][b2][q];
      const float nn = wc * dens[1][0][q] + wa * dens[1][b1][q] + wb * dens[1][b2][q];
      _lut[o * kLutMags + q] = (p - nn) / (p + nn + kEps);
    }
  }
}

}  // namespace cuetrack
