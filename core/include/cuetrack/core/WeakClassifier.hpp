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

#include "cuetrack/core/Features.hpp"

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
struct Code {
  float lnMag = 0.f;
  float wCentre = 0.f, wA = 0.f, wB = 0.f;  // shares of centre, outer bin a, outer bin a+1
  uint8_t a = 0;                            // outer bin index (0..kOrientBins-1)
  uint8_t angleIdx = 0;                     // table row
  uint8_t magIdx = 0;                       // table column
  uint8_t valid = 0;
};

// Quantised log-magnitude: from the float bits of m^2 (exponent + top mantissa bit),
// i.e. steps of a quarter octave of m; exact and the same on every platform.
int magIndex(float mag, FeatureKind kind);
float magOfIndex(int idx, FeatureKind kind);  // the cell's representative magnitude
int angleIndex(float angleRad);
Code encode(const Response& r, FeatureKind kind);

class WeakClassifier {
 public:
  // Fits to n coded responses with boosting weights w and labels y (+1 / -1), then bakes.
  void fit(const Code* codes, const float* w, const int8_t* y, int n, FeatureKind kind);
  float predict(const Code& c) const {
    return c.valid ? _lut[c.angleIdx * kLutMags + c.magIdx] : _invalid;
  }
  float predict(const Response& r) const {
    if (!r.valid) return _invalid;
    return _lut[angleIndex(r.angle) * kLutMags + magIndex(r.mag, _kind)];
  }
  FeatureKind kind() const { return _kind; }

  // GentleBoost's weighted squared error of the binned (histogram) fit of these
  // responses: sum over bins of 4 Wp Wn / (Wp + Wn), in [0, sum w]. Cheap (no
  // lognormal), used to choose among all pool features each round.
  static float binnedError(const Code* codes, const float* w, const int8_t* y, int n);

 private:
  float _lut[kLutCells]{};
  float _invalid = 0.f;
  FeatureKind _kind = FeatureKind::Gray;
};

}  // namespace cuetrack
