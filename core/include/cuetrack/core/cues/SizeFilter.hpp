// 2D: the estimate's size jitters from frame to frame, the target's changes smoothly.
// An alpha-beta filter on ln w and ln h smooths it; its rate term follows a steady zoom
// without lag. The centre is left alone (an object moved by hand turns sharply).
#pragma once

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack {

class SizeFilter2d {
 public:
  void configure(float alpha, float beta) {
    _alpha = alpha;
    _beta = beta;
  }
  bool enabled() const { return _alpha < 1.f; }
  void reset(const Box& b) {
    _logSize[0] = fmath::fastLog(b.w);
    _logSize[1] = fmath::fastLog(b.h);
    _rate[0] = _rate[1] = 0.f;
  }
  // The box with its size filtered, about the same centre.
  Box filter(const Box& b) {
    float side[2] = {b.w, b.h};
    for (int a = 0; a < 2; ++a) {
      const float predicted = _logSize[a] + _rate[a];
      const float residual = fmath::fastLog(side[a]) - predicted;
      _logSize[a] = predicted + _alpha * residual;
      _rate[a] += _beta * residual;
      side[a] = fmath::fastExp(_logSize[a]);
    }
    return Box{b.x + 0.5f * (b.w - side[0]), b.y + 0.5f * (b.h - side[1]), side[0], side[1]};
  }

 private:
  float _alpha = 1.f, _beta = 0.f;
  float _logSize[2] = {0.f, 0.f};  // smoothed ln w, ln h [ln px]
  float _rate[2] = {0.f, 0.f};     // ... and their rates [per frame]
};

}  // namespace cuetrack
