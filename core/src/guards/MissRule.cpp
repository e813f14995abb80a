#include "cuetrack/core/guards/MissRule.hpp"

#include "cuetrack/core/guards/PeakContrast.hpp"

namespace cuetrack {

bool MissRule::miss(const Inputs& in, const DepthGuard& guard) {
  bool miss = (in.is3d && !in.wasLost && !in.onProbation && guard.jumped(in.depthMm)) ||
              PeakContrast::flat(in.contrast);
  // The target may have moved in depth while hidden, but not so far.
  if (in.is3d && (in.wasLost || in.onProbation) && guard.implausibleFind(in.depthMm)) miss = true;
  if (in.onProbation && in.unlikeTarget) miss = true;
  return miss;
}

}  // namespace cuetrack
