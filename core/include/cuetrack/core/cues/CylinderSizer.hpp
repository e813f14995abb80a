// Adaptive cylinder size (beyond the paper; `adaptCylinderSize`): the paper fixes the
// cylinder's D and H at init, and loses a target that turns (its Tank sequence). Here, on
// each learnt frame, the target's silhouette is measured in depth around the estimate
// (measureSilhouette) and D, H and the window's centre move part of the way toward it.
// The init frame calibrates how the user's box relates to that measurement.
#pragma once

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

class CylinderSizer {
 public:
  // One axis: box side / measured extent, and the box centre's offset from the measured
  // midpoint as a fraction of the side. An axis the init frame could not measure
  // plausibly (the slab merges with its support, or is mostly holes) stays invalid: that
  // side stays fixed, as in the paper.
  struct Axis {
    bool valid = false;
    float ratio = 1.f;
    float offset = 0.f;
  };
  // Within this factor the box and the measured extent must agree at init.
  static constexpr float kMaxCalibration = 1.6f;
  static Axis calibrateAxis(float sidePx, float centrePx, float runPx, float runMidPx);

  // gain: part of the way ln D, ln H move per learnt frame; centreGain: likewise the centre.
  void configure(float gain, float centreGain) {
    _gain = gain;
    _centreGain = centreGain;
  }
  void clear() { _x = _y = Axis{}; }
  const Axis& axisX() const { return _x; }
  const Axis& axisY() const { return _y; }
  // At init: the user's box b against the silhouette measured in it (D in mm).
  void calibrate(const Frame& frame, const IntegralChannels& channels, const Box& b,
                 float diameterMm);
  // Moves D, H and the centre of `est` (whose window is b) and of every particle toward
  // the silhouette measured around b; false when nothing was measured or nothing moves.
  bool follow(const Frame& frame, const IntegralChannels& channels, const CameraIntrinsics& k,
              const Box& b, Particle& est, ParticleFilter& filter) const;

 private:
  float _gain = 0.1f, _centreGain = 0.2f;
  Axis _x{}, _y{};
};

}  // namespace cuetrack
