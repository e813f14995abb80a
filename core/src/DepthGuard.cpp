#include "cuetrack/core/DepthGuard.hpp"

namespace cuetrack {

void DepthGuard::update(float zMm, bool confirmed, bool tracking, float dtS) {
  constexpr float kFramePeriod30S = 1.f / 30.f;  // kFollow is per frame at 30 fps
  if (confirmed) _confirmedMm = zMm;
  // The allowance scales with the frame gap.
  const float gap = dtS > kFramePeriod30S ? dtS / kFramePeriod30S : 1.f;
  if (confirmed || (tracking && depthWithin(zMm, _prevMm, 1.f + tuning::depthGuard::kFollow * gap)))
    _learnRefMm = zMm;
  _prevMm = zMm;
}

}  // namespace cuetrack
