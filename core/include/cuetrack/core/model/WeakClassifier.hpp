// One weak classifier over one feature's response (angle, magnitude), after
// Klein & Cremers (ICRA 2011): a centre bin for weak responses, kOrientBins outer
// orientation bins for strong ones, and a bin for "no measurement" (depth holes).
// A response is shared between the two nearest orientation bins (linear in angle)
// and between centre and outer (linear in magnitude between the kind's inner and
// outer thresholds). Per bin and class we accumulate boosting weight x share of
// ln(magnitude) and its square, fit a lognormal by maximum likelihood, and predict
//   f = (p - n) / (p + n) = 2 p/(p+n) - 1  in [-1, 1]   (GentleBoost's regression)
// with p, n the weighted likelihoods of positives and negatives. After fitting, f
// is baked into a lookup table over (quantised angle, quantised log-magnitude), so
// evaluating a particle costs one table read.
#pragma once

#include <cstdint>

#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/model/Features.hpp"

namespace cuetrack {

inline constexpr int kOrientBins = 8;             // outer bins
inline constexpr int kNumBins = kOrientBins + 2;  // + centre (0) + no-measurement (last)
inline constexpr int kInvalidBin = kOrientBins + 1;
inline constexpr int kLutAngles = 32;  // angle steps of the baked table
inline constexpr int kLutMags = 40;    // quarter-octave magnitude steps
inline constexpr int kLutCells = kLutAngles * kLutMags;

// Magnitude thresholds per kind, in the kind's own unit (see Features.hpp).
struct KindBinning {
  float innerMag;  // below: entirely centre bin
  float outerMag;  // above: entirely outer bins
  float minMag;    // smallest magnitude the table resolves (10 octaves above it)
};
// Gray: grey levels (mean differences of halves); depth: mm (the paper: 5 cm / 20 cm);
// colour: chroma C2 in grey levels (the paper's 1 and 3: only near-grey averages,
// below sensor noise, have no meaningful hue).
inline constexpr KindBinning kBinning[3] = {
    {2.f, 10.f, 0.25f},  // Gray
    {50.f, 200.f, 4.f},  // Depth [mm]
    {1.f, 3.f, 0.25f},   // Colour
};
inline const KindBinning& binning(FeatureKind k) {
  return kBinning[static_cast<int>(k)];
}

// A response coded for training: its bin shares, its table cell and ln(magnitude).
// Bins: 0 centre, 1..kOrientBins outer, kInvalidBin no measurement; an invalid
// response puts its whole share (wA = 1) into kInvalidBin, so accumulating needs no branch.
struct Code {
  float lnMag = 0.f;
  float wCentre = 0.f, wA = 0.f, wB = 0.f;  // shares of bin 0, bin binA, bin binB
  uint8_t binA = kInvalidBin;               // outer bin a + 1 (or kInvalidBin)
  uint8_t binB = kInvalidBin;               // outer bin a + 2, wrapped (or kInvalidBin)
  uint8_t angleIdx = 0;                     // table row
  uint8_t magIdx = 0;                       // table column
  bool valid() const { return binA != kInvalidBin; }
};

// Quantised log-magnitude: from the float bits of m^2 (exponent + top mantissa bit),
// i.e. steps of a quarter octave of m; exact and the same on every platform.
inline int magIndexSq(float mag2, FeatureKind kind) {
  const float minMag = binning(kind).minMag;
  const int base = static_cast<int>(fmath::floatBits(minMag * minMag) >> 22);
  const int i = static_cast<int>(fmath::floatBits(mag2) >> 22) - base;
  return i < 0 ? 0 : (i >= kLutMags ? kLutMags - 1 : i);
}
inline int magIndex(float mag, FeatureKind kind) {
  return magIndexSq(mag * mag, kind);
}
float magOfIndex(int idx, FeatureKind kind);  // the cell's representative magnitude

// Sector of the angle of (x, y): kLutAngles sectors of (nearly) equal width. Octant by
// signs and |x| < |y|, then 4 sub-sectors from the ratio min/max through a 64-step
// table of atan (boundaries within 1/64 of the ratio of exact ones). No atan, one
// division; training and particles both use it, so the split is consistent.
struct AngleSectors {
  uint8_t sub[65];
  constexpr AngleSectors() : sub() {
    // tan(k * 11.25 deg), k = 1..3: ratio thresholds of the 4 sub-sectors of an octant.
    constexpr float kTan[3] = {0.19891237f, 0.41421356f, 0.66817864f};
    for (int i = 0; i <= 64; ++i) {
      const float r = (static_cast<float>(i) + 0.5f) / 64.f;
      sub[i] = static_cast<uint8_t>((r > kTan[0]) + (r > kTan[1]) + (r > kTan[2]));
    }
  }
};
inline constexpr AngleSectors kAngleSectors{};

inline int angleIndex(float x, float y) {
  static_assert(kLutAngles == 32, "4 sectors per octant");
  const float ax = x < 0.f ? -x : x, ay = y < 0.f ? -y : y;
  const bool steep = ay > ax;
  const float mx = steep ? ay : ax, mn = steep ? ax : ay;
  const int r = mx > 0.f ? static_cast<int>(mn * 64.f / mx) : 0;  // [0, 64]
  const int s = kAngleSectors.sub[r];
  const int inQuadrant = steep ? 7 - s : s;  // 0..7 from the x axis
  if (y >= 0.f) return x >= 0.f ? inQuadrant : 15 - inQuadrant;
  return x < 0.f ? 16 + inQuadrant : 31 - inQuadrant;
}
Code encode(const Response& r, FeatureKind kind);

// Bin shares of every table cell (its centre angle and representative magnitude),
// per kind: built once, so baking a weak classifier is table lookups.
struct ShareTable {
  float wCentre[kNumFeatureKinds][kLutCells];
  float wA[kNumFeatureKinds][kLutCells];
  float wB[kNumFeatureKinds][kLutCells];
  uint8_t a[kNumFeatureKinds][kLutCells];   // the same along a row (it depends on the angle)
  float lnMag[kNumFeatureKinds][kLutMags];  // ln of each column's representative magnitude
  void build();
};

class WeakClassifier {
 public:
  // Fits to n coded responses with boosting weights w and labels y (+1 / -1), then bakes
  // (with `shares` when given, else computing each cell's shares).
  void fit(const Code* codes, const float* w, const int8_t* y, int n, FeatureKind kind,
           const ShareTable* shares = nullptr);
  float predict(const Code& c) const {
    return c.valid() ? _lut[c.angleIdx * kLutMags + c.magIdx] : _invalid;
  }
  float predict(const Response& r) const {
    if (!r.valid) return _invalid;
    return _lut[angleIndex(r.x, r.y) * kLutMags + magIndexSq(r.magSquared(), _kind)];
  }
  // The table cell a response of a feature of kind `kind` reads: kLutCells when it is
  // not valid. predictCell(cellOf(r, kind())) == predict(r).
  static int cellOf(const Response& r, FeatureKind kind) {
    if (!r.valid) return kLutCells;
    return angleIndex(r.x, r.y) * kLutMags + magIndexSq(r.magSquared(), kind);
  }
  float predictCell(int cell) const { return _lut[cell]; }
  FeatureKind kind() const { return _kind; }

  // GentleBoost's weighted squared error of the binned (histogram) fit of these
  // responses: sum over bins of 4 Wp Wn / (Wp + Wn), in [0, sum w]. Cheap (no
  // lognormal), used to choose among all pool features each round.
  static float binnedError(const Code* codes, const float* w, const int8_t* y, int n);
  // The same when examples [0, split) are all positive and [split, n) all negative
  // (the training set's layout): no per-example label test.
  static float binnedErrorSplit(const Code* codes, const float* w, int split, int n);
  // binnedErrorSplit of four features at once (codes[k] the k-th one's codes): the same
  // sums in the same order, bit for bit, but four independent chains of additions.
  static void binnedErrorSplit4(const Code* const codes[4], const float* w, int split, int n,
                                float err[4]);

 private:
  float _lut[kLutCells + 1]{};  // the last cell: _invalid (for predictCell)
  float _invalid = 0.f;
  FeatureKind _kind = FeatureKind::Gray;
};

}  // namespace cuetrack
